#include "contrib/receivers.h"

#include <cctype>
#include <cmath>

#include <glm/geometric.hpp>

#include "contrib/flux_surfaces.h"
#include "util/error.h"
#include "util/options.h"

namespace brume {

namespace {

using glm::dvec3;

// A function file rcontrib loads once for all the receivers that need it.
void load(ContributionRun& run, const std::string& file, std::vector<std::string>& words) {
    for (const CalDefinition& d : run.definitions)
        if (d.kind == CalDefinition::Kind::File && d.text == file) return;
    run.definitions.push_back({CalDefinition::Kind::File, file});
    words.insert(words.end(), {"-f", file});
}

// The Klems bins of an h=, as Radiance's rfluxmtx names them.
struct KlemsBins {
    const char *file, *function, *count;
};

const KlemsBins* klemsBins(const std::string& h) {
    static const KlemsBins full{"klems_full.cal", "kbin", "Nkbins"}, half{"klems_half.cal", "khbin", "Nkhbins"},
        quarter{"klems_quarter.cal", "kqbin", "Nkqbins"};
    char basis = klemsBasisOf(h);
    return basis == 'f' ? &full : basis == 'h' ? &half : basis == 'q' ? &quarter : nullptr;
}

}  // namespace

std::vector<FluxReceiver> readReceivers(const std::string& path) {
    std::vector<FluxReceiver> out;
    FluxSettings pending;
    for (const FluxSurface& s : readFluxSurfaces(path, "receiver")) {
        for (const auto& [at, words] : s.settings) applyFluxSettings(words, pending, at);
        if (out.empty() || out.back().modifier != s.modifier) {
            FluxReceiver r;
            r.modifier = s.modifier;
            r.settings = pending;
            // As in Radiance, the next group keeps the hemisphere but not the up direction or the output.
            pending.up.reset();
            pending.output.clear();
            out.push_back(r);
        }
        FluxReceiver& r = out.back();
        r.normal += s.area * s.normal;
        r.sources = r.sources && s.source;
        if (s.source && std::abs(s.area - M_PI) > 1e-3) r.narrowSources.push_back(s.name);
    }
    if (out.empty()) throw Error(path + ": no receiver surfaces (polygons, rings or sources)");
    return out;
}

void addReceiver(const FluxReceiver& r, ContributionRun& run, std::vector<std::string>& words) {
    if (r.settings.hemisphere.empty()) throw Error("receiver '" + r.modifier + "': missing hemisphere sampling type (h=)");
    if (!(glm::length(r.normal) > 0)) throw Error("receiver '" + r.modifier + "': undefined normal for hemisphere sampling");
    dvec3 n = glm::normalize(r.normal);
    dvec3 up = upOf(r.settings, n);
    if (!r.settings.output.empty()) {
        run.next.output = r.settings.output;
        words.insert(words.end(), {"-o", r.settings.output});
    }
    char kind = char(std::tolower(static_cast<unsigned char>(r.settings.hemisphere[0])));
    if (kind == 'u' || kind == '1') {
        run.next.binCount = "1";
        run.next.bin = r.sources ? "0" : "if(-Dx*" + formatShort(n.x) + "-Dy*" + formatShort(n.y) + "-Dz*" + formatShort(n.z) + ",0,-1)";
    } else if (kind == 'r' || kind == 't') {
        load(run, "reinhartb.cal", words);
        run.next.parameters = "MF=" + std::to_string(r.settings.size) + ",rNx=" + formatShort(n.x) + ",rNy=" + formatShort(n.y) +
                              ",rNz=" + formatShort(n.z) + ",Ux=" + formatShort(up.x) + ",Uy=" + formatShort(up.y) +
                              ",Uz=" + formatShort(up.z) + ",RHS=" + r.settings.sign + "1";
        run.next.binCount = "Nrbins";
        run.next.bin = "rbin";
        words.insert(words.end(), {"-p", run.next.parameters});
    } else if (const KlemsBins* k = klemsBins(r.settings.hemisphere)) {
        load(run, k->file, words);
        run.next.parameters = std::string("RHS=") + r.settings.sign + "1";
        run.next.binCount = k->count;
        run.next.bin = std::string(k->function) + "(" + formatShort(n.x) + "," + formatShort(n.y) + "," +
                       formatShort(n.z) + "," + formatShort(up.x) + "," + formatShort(up.y) + "," + formatShort(up.z) + ")";
        words.insert(words.end(), {"-p", run.next.parameters});
    } else {
        throw Error("receiver '" + r.modifier + "': hemisphere sampling h=" + r.settings.hemisphere +
                    " is not supported yet (Brume has u, r, t and kf, kh, kq)");
    }
    // Bins over a hemisphere take a whole one: a narrower source would leave bins empty unsaid (Radiance's rule).
    if (kind != 'u' && kind != '1' && !r.narrowSources.empty())
        throw Error("source '" + r.narrowSources.front() + "' must be 180-degrees");
    words.insert(words.end(), {"-bn", run.next.binCount, "-b", run.next.bin, "-m", r.modifier});
    run.addModifier(r.modifier);
}

}  // namespace brume
