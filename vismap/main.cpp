// vismap: whether the signs of a scene can be seen through its smoke, from observers on a grid or along a route,
// at given instants: by the light that reaches the eye (Adrian's visibility level) and by Jin's law (see
// man/vismap.1).
#include <tbb/global_control.h>

#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include "integrator/render_options.h"
#include "medium/smoke.h"
#include "render/progress.h"
#include "render/sequence.h"
#include "scene/reader.h"
#include "util/header.h"
#include "visibility/endurance.h"
#include "visibility/sign_list.h"
#include "visibility/study_checks.h"
#include "visibility/study_report.h"

using namespace brume;

namespace {

struct Options {
    ProgramOptions program;
    RenderSettings render;
    bool irradianceAtHit = false;  // rtrace's -i, which a study has no use for
    std::string signs, waypoints, prefix;
    std::vector<double> grid;      // x0 y0 x1 y1 step z
    std::vector<double> instants;  // none: 0
    StudySettings study;
    double reportInterval = 0;
};

const char* const kUsage =
    "usage: vismap -S signs.txt (-g x0 y0 x1 y1 step z | -wp waypoints.txt) [-T t1,t2,...] [-o prefix] [options] "
    "octree|scene.rad ... > sight.csv\n";

std::vector<double> listOfReals(const std::string& option, const std::string& list) {
    std::vector<double> out;
    std::stringstream in(list);
    for (std::string word; std::getline(in, word, ',');) out.push_back(toReal(option, word));
    if (out.empty() || !std::is_sorted(out.begin(), out.end()) || std::adjacent_find(out.begin(), out.end()) != out.end())
        throw UsageError(option + ": instants must increase (e.g. -T 60,120,180)", kUsage);
    return out;
}

OptionTable makeTable(Options& o) {
    OptionTable t;
    addProgramOptions(t, o.program);
    t.add("-S", 1, "the signs: lines 'polygon emitting|reflecting [Jin's C]'", [&o](const auto& a) { o.signs = a[0]; });
    t.add("-g", 6, "observers on a grid: cells of side step over (x0, y0)-(x1, y1), eyes at height z",
          [&o](const auto& a) {
              o.grid.clear();
              for (const std::string& w : a) o.grid.push_back(toReal("-g", w));
          });
    t.add("-wp", 1, "observers at waypoints: lines 'name x y z'", [&o](const auto& a) { o.waypoints = a[0]; });
    t.add("-o", 1, "prefix of the files written: losses, summary, JSON; maps with -g", [&o](const auto& a) { o.prefix = a[0]; });
    addIntOption(t, "-vr", o.study.rays, "rays to each sign and to its background per observer and instant");
    addIntOption(t, "-vp", o.study.passes, "passes of -vr rays at most: more for sight lines near the criterion");
    addRealOption(t, "-vl", o.study.criteria.minimumLevel, "the visibility level a visible sign reaches");
    addRealOption(t, "-va", o.study.criteria.observer.age, "the observer's age (years, 23-75)");
    addRealOption(t, "-vt", o.study.criteria.observer.seconds, "the observation time (s)");
    addRealOption(t, "-vc", o.study.criteria.minimumCoverage,
                  "the share of a line with smoke data below which no sign is called visible (0: the rest clear air)");
    t.addBool("-vj", o.study.jinOnly, "Jin's law and the local criteria only: no light traced (fast)");
    t.addBool("-vf", o.study.criteria.jinViewAngle,
              "Jin's S times the cosine of the angle the eye sees the sign's front at (FDSVisMap's view-angle factor)");
    addRealOption(t, "-vx", o.study.criteria.jinCap, "Jin's S at most this (m; FDSVisMap and FDS cap it at 30)");
    addRealOption(t, "-vs", o.study.criteria.leastLocalVisibility,
                  "the least local visibility C/K at the eye (m; Smokeview's criterion, 5 or 10; 0: none)");
    t.add("-vk", 1, "the K of Jin's law: 633 (soot's at 633 nm, as FDS's VISIBILITY; default) or photopic",
          [&o](const auto& a) {
              if (a[0] == "633") o.study.quoted = QuotedExtinction::At633nm;
              else if (a[0] == "photopic") o.study.quoted = QuotedExtinction::Photopic;
              else throw UsageError("-vk: expected 633 or photopic, not '" + a[0] + "'", kUsage);
          });
    addRealOption(t, "-t", o.reportInterval, "seconds between progress reports (0: none, or a live line on a terminal)");
    addRenderOptions(t, o.render, o.irradianceAtHit);
    t.remove("-T");
    t.add("-T", 1, "instants t1,t2,... (s) of time-varying content",
          [&o](const auto& a) { o.instants = listOfReals("-T", a[0]); });
    return t;
}

std::vector<StudySign> loadSigns(const std::string& path, const Scene& scene, int rays) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot be opened");
    std::vector<StudySign> out;
    for (const SignEntry& e : readSignList(in, path)) {
        try {
            out.push_back(studySign(signFromScene(scene, e.name, e.kind, e.jinConstant), rays));
        } catch (const Error& error) {
            throw Error(e.where + ": " + error.what());
        }
    }
    return out;
}

std::vector<Observer> loadObservers(const Options& o, const std::optional<ObserverGrid>& grid) {
    if (grid) return gridObservers(*grid, o.grid[5]);
    std::ifstream in(o.waypoints);
    if (!in) throw Error(o.waypoints + ": cannot be opened");
    return readWaypoints(in, o.waypoints);
}

int run(int argc, char** argv) {
    Options o;
    OptionTable table = makeTable(o);
    auto line = parseCommandLine(argc, argv, table, o.program, kUsage, "Multithreading\nReproducibleSampling\n");
    if (!line) return 0;
    checkRenderSettings(o.render);
    if (o.irradianceAtHit) throw UsageError("-i: a study traces the light that reaches the eye", kUsage);
    if (o.signs.empty()) throw UsageError("no signs (-S)", kUsage);
    if (o.study.rays < 1) throw UsageError("-vr: at least one ray", kUsage);
    if (o.study.passes < 1) throw UsageError("-vp: at least one pass", kUsage);
    if (!(o.study.criteria.jinCap > 0)) throw UsageError("-vx: a distance > 0", kUsage);
    if (!(o.study.criteria.leastLocalVisibility >= 0)) throw UsageError("-vs: a distance >= 0", kUsage);
    if (!(o.study.criteria.minimumCoverage >= 0 && o.study.criteria.minimumCoverage <= 1))
        throw UsageError("-vc: a share, from 0 to 1", kUsage);
    if (o.grid.empty() == o.waypoints.empty()) throw UsageError("give observers either on a grid (-g) or at waypoints (-wp)", kUsage);
    std::optional<ObserverGrid> grid;
    if (!o.grid.empty()) grid = makeGrid(o.grid[0], o.grid[1], o.grid[2], o.grid[3], o.grid[4]);
    std::vector<Observer> observers = loadObservers(o, grid);
    setSpectralSampling(o.render.sampling);
    Scene scene = loadScene(line->scene);
    std::vector<StudySign> signs = loadSigns(o.signs, scene, o.study.rays);
    std::vector<double> instants = o.instants.empty() ? std::vector<double>{0} : o.instants;
    RenderScene renderScene(scene, o.render.materials);
    checkInstants(renderScene.smoke(), instants);
    for (const std::string& w : noDataWarnings(renderScene.smoke())) warn(w);
    Sequence sequence(scene, renderScene, o.render);
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(o.program.threads));
    tbb::global_control stack(tbb::global_control::thread_stack_size, size_t(64) << 20);

    const VisibilityStudy study(std::move(observers), std::move(signs), o.study);
    for (const std::string& w : studyWarnings(study, renderScene.geometry(), renderScene.smoke())) warn(w);
    StudyReport report(study, stdout, {o.prefix, grid, commandLine(line->command), instants, renderScene.smoke()});
    Endurance endurance(study.observers().size(), study.signs().size());
    ProgressMeter progress("vismap", o.reportInterval);
    progress.start(long((o.study.jinOnly ? study.lines() : study.firstPassRays()) * instants.size()));
    for (double t : instants) {
        std::vector<SightLine> lines = study.at(t, sequence, renderScene, [&] { progress.advance(1, 1); });
        report.instant(t, lines);
        endurance.add(t, lines, study);
    }
    progress.finish();
    report.finish(endurance);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return runReportingErrors([&] { return run(argc, argv); });
}
