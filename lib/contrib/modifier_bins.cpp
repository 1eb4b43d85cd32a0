#include "contrib/modifier_bins.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <unordered_map>

#include "cal/compiler.h"
#include "cal/embedded.h"
#include "cal/evaluator.h"
#include "scene/raypath.h"
#include "util/error.h"

namespace brume {

namespace {

// An -e expression as a definition: Radiance's take a missing final ';'.
std::string terminated(std::string text) {
    size_t end = text.find_last_not_of(" \t\n");
    if (end != std::string::npos && text[end] != ';') text += ';';
    return text;
}

// A definition's text as read once for every modifier: an -e expression (Radiance's take a missing final ';'),
// or an -f file's, which may knowingly redefine what rayinit.cal defines (loaded without warnings).
struct LoadedDefinition {
    FileText text;
    bool file;
};

std::vector<LoadedDefinition> loaded(const std::vector<CalDefinition>& definitions) {
    std::vector<LoadedDefinition> out;
    for (const CalDefinition& d : definitions)
        if (d.kind == CalDefinition::Kind::Expression) out.push_back({{"-e " + d.text, terminated(d.text)}, false});
        else out.push_back({readLibraryFile(d.text, cal::embeddedCalFiles(), "function file"), true});
    return out;
}

// The definitions every modifier's bins see, then its parameters ("a=1,b=2"), over Brume's rayinit.cal.
void loadDefinitions(cal::Library& library, const std::vector<LoadedDefinition>& definitions,
                     const std::string& parameters) {
    for (const LoadedDefinition& d : definitions) {
        if (d.file) library.redefine(d.text.text, d.text.origin);
        else library.loadText(d.text.text, d.text.origin);
    }
    if (parameters.empty()) return;
    std::string text = parameters;
    std::replace(text.begin(), text.end(), ',', ';');
    library.redefine(terminated(text), "-p " + parameters);
}

// The value of a bin expression that is a plain number.
std::optional<double> number(const std::string& text) {
    char* end = nullptr;
    double v = std::strtod(text.c_str(), &end);
    if (end == text.c_str()) return std::nullopt;
    while (*end == ' ' || *end == '\t') ++end;
    return *end ? std::nullopt : std::optional<double>(v);
}

// Whether the definitions are Brume's own reinhartb.cal alone: by its text, as a file of that name in the
// current directory or along RAYPATH may be another.
bool shippedReinhartOnly(const std::vector<LoadedDefinition>& definitions) {
    if (definitions.size() != 1 || !definitions[0].file) return false;
    for (const EmbeddedFile& f : cal::embeddedCalFiles())
        if (f.name == "reinhartb.cal") return definitions[0].text.text == f.text;
    return false;
}

// rbin of Brume's reinhartb.cal with the parameters the program gives, natively; nothing with jitter or a
// fractional MF (the .cal then).
std::optional<ReinhartBins> nativeReinhart(const cal::Library& library) {
    cal::Compiler compiler(library);
    std::vector<cal::ExprId> ids;
    for (const char* name : {"MF", "RHS", "JTR", "rNx", "rNy", "rNz", "Ux", "Uy", "Uz"})
        ids.push_back(compiler.expression(name, {}, {"-p", 1}));
    cal::Program program = std::move(compiler).finish();
    cal::Evaluator evaluator(program);
    evaluator.begin(cal::Channels{});
    double v[9];
    for (int i = 0; i < 9; ++i) v[i] = evaluator(ids[i]);
    if (v[2] != 0 || !(v[0] >= 1) || v[0] != std::floor(v[0]) || v[0] > 64) return std::nullopt;
    return ReinhartBins(ReinhartFrame{v[0], v[1], {v[3], v[4], v[5]}, {v[6], v[7], v[8]}});
}

// The objects that may modify others (those a contribution's modifier may be), by name.
std::unordered_map<std::string, std::vector<int>> modifiersByName(const Scene& scene) {
    std::unordered_map<std::string, std::vector<int>> found;
    for (size_t i = 0; i < scene.objects.size(); ++i)
        if (isModifierType(scene.objects[i].type)) found[scene.objects[i].name].push_back(int(i));
    return found;
}

}  // namespace

ModifierBins::ModifierBins(const Scene& scene, const RenderScene& render, const std::vector<CalDefinition>& definitions,
                           const std::vector<ModifierRequest>& requests)
    : byObject_(scene.objects.size(), -1) {
    const auto named = modifiersByName(scene);
    const std::vector<LoadedDefinition> texts = loaded(definitions);
    for (const ModifierRequest& r : requests) {
        if (r.name == "void") throw Error("cannot track 'void' modifier");
        auto objects = named.find(r.name);
        if (objects == named.end()) throw Error("modifier '" + r.name + "' is not in the scene");
        for (int o : objects->second) {
            if (!render.emitter(o))
                throw Error("modifier '" + r.name + "' (" + scene.objects[o].type +
                            ") is no light source: Brume tells the contributions of light, glow, illum and spotlight only");
            if (byObject_[o] >= 0) throw Error("duplicate modifier '" + r.name + "'");
            byObject_[o] = int(modifiers_.size());
        }
        // A constant bin is one bin, whatever -bn says, and nothing to compile (thousands of suns' modifiers).
        if (std::optional<double> constant = number(r.bin)) {
            if (!(std::abs(*constant) < 0.5)) throw Error("illegal non-zero constant for bin (" + r.bin + ")");
            modifiers_.push_back(Tallied{r.name, 1, columns_++, {}, {}, true, std::nullopt, r.output});
            continue;
        }
        cal::Library library;
        loadDefinitions(library, texts, r.parameters);
        cal::Compiler compiler(library);
        cal::ExprId bin = compiler.expression(r.bin, {}, {"-b", 1});
        cal::ExprId count = compiler.expression(r.binCount, {}, {"-bn", 1});
        Tallied t{r.name, 1, columns_, std::move(compiler).finish(), bin, false, std::nullopt, r.output};
        if (r.bin == "rbin" && shippedReinhartOnly(texts)) t.reinhart = nativeReinhart(library);
        cal::Evaluator evaluator(t.program);
        evaluator.begin(cal::Channels{});
        double n = evaluator(count);
        if (!(n >= 0.5) || n > 1e8) throw Error("unspecified or illegal bin count for modifier '" + r.name + "'");
        t.bins = int(n + 0.5);
        columns_ += t.bins;
        modifiers_.push_back(std::move(t));
    }
}

}  // namespace brume
