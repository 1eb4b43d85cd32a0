// mkcache: an irradiance cache file (-af) made ahead of rendering, from the points rtrace will be given or the
// picture rpict will render (see man/mkcache.1). It writes nothing on its standard output.
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <exception>
#include <iostream>

#include "integrator/render_options.h"
#include "io/ray_reader.h"
#include "render/picture_options.h"
#include "render/progress.h"
#include "render/sequence.h"
#include "scene/reader.h"
#include "view/view_options.h"

using namespace brume;

namespace {

const char* const kUsage =
    "usage: mkcache [options] -af file octree|scene.rad ... < points\n"
    "       mkcache [options] -af file view options [-x N -y N] octree|scene.rad ...\n";

struct Options {
    ProgramOptions program;
    RenderSettings render;
    PictureSettings picture;  // its `irradiance` is -i, for points and pictures alike
    View view;
    bool irradiance = false, limitDistance = false;
    char inFormat = 'a';
    double reportInterval = 0;
};

OptionTable makeTable(Options& o) {
    OptionTable t;  // mkcache's own options first, then those it shares with rtrace and rpict
    t.addBool("-I", o.irradiance, "points are sensors: irradiance at the origin, the direction being the surface normal");
    t.addBool("-ld", o.limitDistance, "limit distance to the length of the direction vector");
    // rtrace's two-letter forms (-faa) are taken too, so its options can be copied; the output letter is moot.
    t.addAttached("-f", "input format: a (ascii), f (float), d (double)", [&o](const std::string& v) {
        if (v.empty() || v.size() > 2 || std::string("afd").find(v[0]) == std::string::npos ||
            (v.size() == 2 && std::string("afdc").find(v[1]) == std::string::npos))
            throw Error("command line error at '-f" + v + "'");
        o.inFormat = v[0];
    }, [&o] { return std::string(1, o.inFormat); });
    addRealOption(t, "-t", o.reportInterval, "seconds between progress reports (0: none, or a live line on a terminal)");
    addProgramOptions(t, o.program);
    addViewOptions(t, o.view);
    addPictureOptions(t, o.picture);
    addRenderOptions(t, o.render, o.picture.irradiance);
    return t;
}

// Whether the command line gives a view: then mkcache renders its picture, with rpict's defaults, so that the
// cache file suits `rpict` given the same options.
bool namesView(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    expandResponseFiles(args);
    return std::any_of(args.begin(), args.end(),
                       [](const std::string& w) { return w.starts_with("-v") && w != "-version"; });
}

struct Batch {
    uint64_t first;  // index of its first ray, which seeds the samples
    std::vector<InputRay> rays;
};

// Every point on the standard input, in rtrace's batches; read first so that progress knows the total. A
// bad point ends them, its Error kept in `error`: the points before it are cached, as rtrace would answer them.
std::vector<Batch> readPoints(char format, std::exception_ptr& error) {
    RayReader reader(std::cin, format, "(stdin)");
    RayBatches batches(reader, kRayBatchSize, 0);
    std::vector<Batch> all;
    try {
        for (std::vector<InputRay> rays; batches.next(rays);) all.push_back({batches.first(), rays});
    } catch (const Error&) {
        error = std::current_exception();
    }
    return all;
}

// Traces the points as rtrace would, discarding the values: each batch makes the records rtrace's would, and
// they go to the file after it.
void cachePoints(const Options& o, Sequence& sequence, ProgressMeter& progress) {
    std::exception_ptr error;
    std::vector<Batch> batches = readPoints(o.inFormat, error);
    long total = 0;
    for (const Batch& b : batches) total += long(b.rays.size());
    progress.start(total);
    const Integrator& integrator = sequence.integrator();
    double time = o.render.time.value_or(0);
    for (const Batch& b : batches) {
        sequence.run(b.rays.size(), time, [&](size_t i, WorkItem& item) {
            const InputRay& in = b.rays[i];
            if (in.zero) return;
            RayQuery q{in.org, in.dir, b.first + i, time, o.limitDistance ? in.maxDistance : 0};
            if (o.irradiance) integrator.irradiance(q, item);
            else if (o.picture.irradiance) integrator.irradianceAtHit(q, item);
            else integrator.trace(q, item);
        });
        progress.advance(long(b.rays.size()), long(b.rays.size()));
    }
    progress.finish();
    if (error) std::rethrow_exception(error);
}

// Renders the view's picture as rpict would, discarding it: the records it needs go to the file.
void cachePicture(const Options& o, Sequence& sequence, ProgressMeter& progress) {
    PictureSettings p = o.picture;
    fitPictureResolution(o.view, p);
    sequence.render({o.view, 0, o.render.time}, p, &progress);
}

int run(int argc, char** argv) {
    std::ios::sync_with_stdio(false);  // std::cin reads points; unsynchronised it reads them in blocks
    Options o;
    bool picture = namesView(argc, argv);
    if (picture) usePictureDefaults(o.render);
    OptionTable table = makeTable(o);
    auto line = parseCommandLine(argc, argv, table, o.program, kUsage, "Multithreading\nReproducibleSampling\n");
    if (!line) return 0;
    checkRenderSettings(o.render);
    setSpectralSampling(o.render.sampling);
    if (o.render.cacheFile.empty()) throw Error("no cache file: give one with -af file");
    if (o.irradiance && o.picture.irradiance) throw Error("-I and -i are exclusive");
    if (picture) o.view.validate();
    Scene scene = loadScene(line->scene);
    RenderScene renderScene(scene, o.render.materials);
    if (!o.render.usesCache()) throw Error("nothing to cache: the irradiance cache needs -ab > 0, -aa > 0 and -ad > 0");
    Sequence sequence(scene, renderScene, o.render);

    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(o.program.threads));
    tbb::global_control stack(tbb::global_control::thread_stack_size, size_t(64) << 20);  // deep ray trees
    ProgressMeter progress("mkcache", o.reportInterval);
    if (picture) cachePicture(o, sequence, progress);
    else cachePoints(o, sequence, progress);
    std::fprintf(stderr, "mkcache: %s: %s\n", o.render.cacheFile.c_str(), sequence.cache()->summary().c_str());
    if (sequence.volumes())
        std::fprintf(stderr, "mkcache: %s: in media, %s\n", o.render.cacheFile.c_str(), sequence.volumes()->summary().c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return runReportingErrors([&] { return run(argc, argv); });
}
