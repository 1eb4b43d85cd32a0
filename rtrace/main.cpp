// rtrace: values along rays read from standard input, as Radiance's rtrace (see man/rtrace.1).
#include <tbb/global_control.h>

#include <algorithm>
#include <bit>
#include <cstdio>
#include <iostream>
#include <optional>

#include "integrator/render_options.h"
#include "io/ray_reader.h"
#include "io/value_writer.h"
#include "medium/smoke.h"
#include "render/sequence.h"
#include "render/shared_bounces.h"
#include "scene/reader.h"
#include "util/header.h"

using namespace brume;

namespace {

struct Options {
    ProgramOptions program;
    RenderSettings render;
    bool irradiance = false, irradianceAtHit = false, header = true, limitDistance = false;
    std::string outputSpec = "v";
    ColorOutput color;
    char inFormat = 'a', outFormat = 'a';
    int xres = 0, yres = 0;
    double shareBounces = kShareBouncesDefault;  // -aS, for sensors (-I, -i)
};

OptionTable makeTable(Options& o) {
    OptionTable t;
    addProgramOptions(t, o.program);
    t.add("-x", 1, "flush interval (x resolution)", [&o](const auto& a) { o.xres = toInt("-x", a[0]); },
          [&o] { return std::to_string(o.xres); });
    t.add("-y", 1, "y resolution", [&o](const auto& a) { o.yres = toInt("-y", a[0]); },
          [&o] { return std::to_string(o.yres); });
    t.addBool("-ld", o.limitDistance, "limit distance to the length of the direction vector");
    t.addBool("-h", o.header, "output header");
    t.addBool("-I", o.irradiance, "irradiance at the ray origin, the direction being the surface normal");
    t.addAttached("-f", "input/output formats: a (ascii), f (float), d (double), c (RGBE, output only)",
                  [&o](const std::string& v) {
                      if (v.empty() || v.size() > 2 || std::string("afd").find(v[0]) == std::string::npos ||
                          (v.size() == 2 && std::string("afdc").find(v[1]) == std::string::npos))
                          throw Error("command line error at '-f" + v + "'");
                      o.inFormat = v[0];
                      o.outFormat = v.size() == 2 ? v[1] : v[0];
                  },
                  [&o] { return std::string(1, o.inFormat) + o.outFormat; });
    t.addAttached("-o", "output values: o d v V w W l L c p n N s m M r x R X ~", [&o](const std::string& v) {
        o.outputSpec = v;
    }, [&o] { return o.outputSpec; });
    addRenderOptions(t, o.render, o.irradianceAtHit);
    addShareBouncesOption(t, o.shareBounces);
    addColorOutputOptions(t, o.color, true);
    t.addAttached("-ap", "photon maps (not supported)",
                  [](const std::string&) { throw Error("photon maps (-ap) are not supported by Brume"); });
    for (const char* name : {"-ti", "-te", "-tI", "-tE"}) t.addUnsupported(name, 1, "trace include/exclude");
    t.addUnsupported("-P", 1, "persistent mode");
    t.addUnsupported("-PP", 1, "persistent mode");
    return t;
}

const char* const kUsage = "usage: rtrace [options] octree|scene.rad ... < rays\n";

// Radiance's header: the octree's header, the command, the software, NCOMP, WAVELENGTH_SPLITS or PRIMARIES,
// and FORMAT.
void writeHeader(const Scene& scene, const std::vector<std::string>& command, const ValueWriter& writer,
                 const ColorOutput& color, char format) {
    std::string h;
    if (scene.headerLines.empty()) h += "#?RADIANCE\n";
    for (const std::string& line : scene.headerLines)
        if (line.rfind("FORMAT=", 0) != 0) h += line + "\n";
    h += commandLine(command) + "\n" + softwareAndDates();
    if (writer.components() > 0) h += "NCOMP=" + std::to_string(writer.components()) + "\n";
    for (const std::string& line : color.headerLines()) h += line + "\n";
    if (format == 'f' || format == 'd') h += std::string("BigEndian=") + (std::endian::native == std::endian::big ? "1" : "0") + "\n";
    endHeader(h, writer.formatName(), stdout);
    std::fputs(h.c_str(), stdout);
}

int run(int argc, char** argv) {
    std::ios::sync_with_stdio(false);  // std::cin reads rays; unsynchronised it reads them in blocks
    Options o;
    OptionTable table = makeTable(o);
    auto line = parseCommandLine(argc, argv, table, o.program, kUsage,
                                 "Multithreading\nIrradianceCalc\nImmediateIrradiance\nDistanceLimiting\nReproducibleSampling\n");
    if (!line) return 0;
    checkRenderSettings(o.render);
    if (o.irradiance && o.irradianceAtHit) throw Error("-I and -i are exclusive");
    setSpectralSampling(o.render.sampling);
    Scene scene = loadScene(line->scene);
    RenderScene renderScene(scene, o.render.materials);
    const double instant = o.render.time.value_or(0);
    checkInstants(renderScene.smoke(), {&instant, 1});
    for (const std::string& w : noDataWarnings(renderScene.smoke())) warn(w);
    Sequence sequence(scene, renderScene, o.render);
    const Integrator& integrator = sequence.integrator();
    ValueWriter writer(stdout, o.outputSpec, o.outFormat, scene, o.color);
    if (o.header) writeHeader(scene, line->command, writer, o.color, o.outFormat);
    if (o.xres > 0 && o.yres > 0) std::printf("-Y %8d +X %8d\n", o.yres, o.xres);

    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(o.program.threads));
    tbb::global_control stack(tbb::global_control::thread_stack_size, size_t(64) << 20);  // deep ray trees
    RayReader reader(std::cin, o.inFormat, "(stdin)");
    long limit = o.yres > 0 ? (o.xres > 1 ? long(o.xres) * o.yres : o.yres) : 0;
    long flushEvery = (o.yres == 0 || o.xres <= 1) ? o.xres : 0;
    // Where the cache would serve them (-aa > 0), sensors share their bounces rather than look records up,
    // unless a ray tree is asked for (the shared paths are no one sensor's) or a cache file (its records are
    // what is asked for). -aa 0 stays path tracing, each sensor's paths its own.
    std::optional<SharedBounces> shared;
    size_t batchSize = kRayBatchSize;
    if ((o.irradiance || o.irradianceAtHit) && o.shareBounces > 0 && o.render.usesCache() && !writer.tracing() &&
        o.render.cacheFile.empty() && sharesBounces(renderScene, o.render)) {
        int channels = Spectrum(0.f).size();
        shared.emplace(o.shareBounces, continuationsPerCell(o.render.ambientDivisions), channels, size_t(channels),
                       renderScene.geometry().origin());
        batchSize = std::clamp<size_t>(kSharedBouncesPerBatch / size_t(o.render.ambientDivisions), 1, batchSize);
    }
    RayBatches batches(reader, flushEvery > 0 ? size_t(flushEvery) : batchSize, limit);
    dvec3 lastOrg(0), lastDir(0);
    std::vector<InputRay> rays;
    std::vector<RayRecord> records;
    std::vector<RayTree> trees;
    while (batches.next(rays)) {
        records.assign(rays.size(), RayRecord{});
        trees.assign(writer.tracing() ? rays.size() : 0, RayTree{{}, writer.tracesShadowRays()});
        uint64_t base = batches.first();
        auto trace = [&](size_t i, WorkItem& item) {
            const InputRay& in = rays[i];
            if (in.zero) return;
            RayTree* tree = trees.empty() ? nullptr : &trees[i];
            RayQuery q{in.org, in.dir, base + i, instant, o.limitDistance ? in.maxDistance : 0};
            if (o.irradiance) records[i] = integrator.irradiance(q, item, tree);
            else if (o.irradianceAtHit) records[i] = integrator.irradianceAtHit(q, item, tree);
            else records[i] = integrator.trace(q, item, tree);
        };
        if (shared) {
            shared->reset(rays.size());
            sequence.runPaths(rays.size(), instant, [&](size_t i, WorkItem& item) {
                WorkItem sharing{item.scratch, nullptr, nullptr, &shared->of(i)};
                trace(i, sharing);
            });
            shared->resolveValues(sequence, integrator, instant, base, records);
        } else {
            sequence.run(rays.size(), instant, trace);
        }
        for (size_t i = 0; i < rays.size(); ++i) {
            InputRay in = rays[i];
            if (in.zero) {
                in.org = lastOrg, in.dir = lastDir;
                records[i].point = lastOrg;
            } else if (o.irradiance) {
                // Radiance reports the sensor ray as it traced it: just above the point, looking down.
                in.org = in.org + 1.1e-4 * in.dir, in.dir = -in.dir;
            }
            if (!trees.empty()) writer.writeTree(trees[i]);
            writer.write({in.org, in.dir, &records[i]});
            lastOrg = in.org, lastDir = in.dir;
            if (in.zero) std::fflush(stdout);
        }
        if (flushEvery > 0) std::fflush(stdout);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return runReportingErrors([&] { return run(argc, argv); });
}
