// vismap: whether the signs of a scene can be seen through its smoke, from observers on a grid or along a route,
// at given instants: by the light that reaches the eye (Adrian's visibility level) and by Jin's law (see
// man/vismap.1).
#include <tbb/global_control.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <sstream>

#include "integrator/render_options.h"
#include "io/picture.h"
#include "medium/smoke.h"
#include "render/progress.h"
#include "render/sequence.h"
#include "scene/reader.h"
#include "spectrum/color_output.h"
#include "spectrum/colorimetry.h"
#include "util/header.h"
#include "util/pending_file.h"
#include "visibility/observers.h"
#include "visibility/sight.h"
#include "visibility/sign_list.h"

using namespace brume;

namespace {

struct Options {
    ProgramOptions program;
    RenderSettings render;
    bool irradianceAtHit = false;  // rtrace's -i, which a study has no use for
    std::string signs, waypoints, prefix;
    std::vector<double> grid;      // x0 y0 x1 y1 step z
    std::vector<double> instants;  // none: 0
    int rays = 32;
    int passes = 4;  // passes of rays at most, the later ones for sight lines whose verdict is uncertain
    VisibilityCriteria criteria{{}, 10, 0.5};
    QuotedExtinction quoted = QuotedExtinction::At633nm;  // the K of Jin's law and of the optical depth column
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
    t.add("-o", 1, "prefix of the maps written (with -g)", [&o](const auto& a) { o.prefix = a[0]; });
    addIntOption(t, "-vr", o.rays, "rays to each sign and to its background per observer and instant");
    addIntOption(t, "-vp", o.passes, "passes of -vr rays at most: more for sight lines near the criterion");
    addRealOption(t, "-vl", o.criteria.minimumLevel, "the visibility level a visible sign reaches");
    addRealOption(t, "-va", o.criteria.observer.age, "the observer's age (years, 23-75)");
    addRealOption(t, "-vt", o.criteria.observer.seconds, "the observation time (s)");
    addRealOption(t, "-vc", o.criteria.minimumCoverage,
                  "the share of a line with smoke data below which no sign is called visible (0: the rest clear air)");
    t.add("-vk", 1, "the K of Jin's law: 633 (soot's at 633 nm, as FDS's VISIBILITY; default) or photopic",
          [&o](const auto& a) {
              if (a[0] == "633") o.quoted = QuotedExtinction::At633nm;
              else if (a[0] == "photopic") o.quoted = QuotedExtinction::Photopic;
              else throw UsageError("-vk: expected 633 or photopic, not '" + a[0] + "'", kUsage);
          });
    addRealOption(t, "-t", o.reportInterval, "seconds between progress reports (0: none, or a live line on a terminal)");
    addRenderOptions(t, o.render, o.irradianceAtHit);
    t.remove("-T");
    t.add("-T", 1, "instants t1,t2,... (s) of time-varying content",
          [&o](const auto& a) { o.instants = listOfReals("-T", a[0]); });
    return t;
}

// Every ray of one instant: from an observer's eye to a point on a sign or on the band around it.
struct Aim {
    size_t pair;  // observer × signs + sign
    bool onSign;
    dvec3 target;
};

struct SignTargets {
    Sign sign;
    std::vector<dvec3> on, around;
};

std::vector<SignTargets> loadSigns(const std::string& path, const Scene& scene, int rays) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot be opened");
    std::vector<SignTargets> out;
    for (const SignEntry& e : readSignList(in, path)) {
        try {
            Sign s = signFromScene(scene, e.name, e.kind, e.jinConstant);
            out.push_back({s, pointsOnSign(s, rays), pointsAroundSign(s, rays)});
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

bool facing(const Sign& s, const dvec3& eye) { return glm::dot(s.shape.normal, eye - s.centre) > 0; }

// The rays of one instant: for each observer and sign it faces, the sign's points and the band's.
std::vector<Aim> aims(const std::vector<Observer>& observers, const std::vector<SignTargets>& signs) {
    std::vector<Aim> out;
    for (size_t o = 0; o < observers.size(); ++o)
        for (size_t s = 0; s < signs.size(); ++s) {
            if (!facing(signs[s].sign, observers[o].eye)) continue;
            for (const dvec3& p : signs[s].on) out.push_back({o * signs.size() + s, true, p});
            for (const dvec3& p : signs[s].around) out.push_back({o * signs.size() + s, false, p});
        }
    return out;
}

// The luminances one observer's rays to one sign brought, summed over passes.
struct Tally {
    double signSum = 0, signSquares = 0, backgroundSum = 0, backgroundSquares = 0;
    int signRays = 0, signHits = 0, backgroundRays = 0;
};

double mean(double sum, int n) { return n ? sum / n : 0; }
// The standard error of a mean of n values from their sum and sum of squares (0 for fewer than two).
double standardError(double sum, double squares, int n) {
    if (n < 2) return 0;
    double m = sum / n;
    return std::sqrt(std::max(0.0, squares / n - m * m) / (n - 1));
}

void writeCsvHead() {
    std::printf("instant_s,observer,x,y,z,sign,kind,distance_m,sign_cd_m2,background_cd_m2,contrast,size_arcmin,"
                "threshold_cd_m2,visibility_level,verdict,seen_share,optical_depth,mean_extinction_1_m,jin_distance_m,"
                "jin_verdict,visibility_level_se,extinction_quoted,data_share\n");
}

// The K the optical depth and Jin's columns quote (-vk).
const char* quotedName(QuotedExtinction quoted) { return quoted == QuotedExtinction::At633nm ? "633nm" : "photopic"; }

void writeCsvRow(double t, const Observer& o, const Sign& s, const SightMeasure& m, const SightJudgement& j,
                 QuotedExtinction quoted) {
    std::printf("%.10g,%s,%.10g,%.10g,%.10g,%s,%s,%.4g,%.5g,%.5g,%.4g,%.4g,%.4g,%.4g,%s,%.3g,%.4g,%.4g,%.4g,%s,%.3g,%s,%.3g\n",
                t, o.name.c_str(),
                o.eye.x, o.eye.y, o.eye.z, s.name.c_str(), s.kind == SignKind::Emitting ? "emitting" : "reflecting",
                m.distance, m.signLuminance, m.backgroundLuminance, j.contrast, j.angularSize, j.threshold,
                j.visibilityLevel, verdictName(j.verdict), m.seenShare, m.opticalDepth, j.meanExtinction,
                j.jinDistance, j.jinVisible ? "visible" : j.jinNoData ? "no-data" : "not-visible", j.levelError,
                quotedName(quoted), m.coverage);
}

// A map over the grid's cells, one value per observer (the same in R, G and B: a data picture for falsecolor).
void writeMap(const std::string& path, const ObserverGrid& g, const std::vector<Observer>& observers,
              const std::vector<double>& values, const std::string& what, const std::string& command) {
    Picture p;
    p.width = g.columns, p.height = g.rows;
    p.pixels.assign(size_t(p.width) * size_t(p.height) * 3, 0.f);
    for (size_t i = 0; i < observers.size(); ++i)
        for (int c = 0; c < 3; ++c) p.at(observers[i].column, observers[i].row)[c] = float(std::max(0.0, values[i]));
    p.header = {command, "VISMAP=" + what,
                "VISMAP_GRID= x0 " + std::to_string(g.x0) + " y0 " + std::to_string(g.y0) + " step " +
                    std::to_string(g.step) + " (column 0 at x0, row 0 at the largest y)"};
    writeWhole(path, [&](std::ostream& out) { writeRadiancePicture(out, p); });
}

// Whether a sight line's verdict could go the other way by the rays' noise: its visibility level within two
// standard errors of the criterion (a sign seen, not hidden).
bool uncertain(const SightJudgement& j, const VisibilityCriteria& c) {
    bool seen = j.verdict == Verdict::Visible || j.verdict == Verdict::BelowThreshold;
    return seen && std::abs(j.visibilityLevel - c.minimumLevel) < 2 * j.levelError;
}

// How long each sign stays visible from each observer, instant by instant: by the light and by Jin's law.
struct Endurance {
    std::vector<double> light, jin;  // the last instant through which the sign stayed visible from the first
    std::vector<bool> lightGoing, jinGoing;
    explicit Endurance(size_t pairs) : light(pairs, 0), jin(pairs, 0), lightGoing(pairs, true), jinGoing(pairs, true) {}
    void add(size_t pair, double t, const SightJudgement& j) {
        lightGoing[pair] = lightGoing[pair] && j.verdict == Verdict::Visible;
        jinGoing[pair] = jinGoing[pair] && j.jinVisible;
        if (lightGoing[pair]) light[pair] = t;
        if (jinGoing[pair]) jin[pair] = t;
    }
};

// Adds what the rays `traced` (indices into `rays`) brought, `records` in the same order, to their sight lines.
void addTo(std::vector<Tally>& tallies, const std::vector<size_t>& traced, const std::vector<Aim>& rays,
           const std::vector<RayRecord>& records, const std::vector<SignTargets>& signs) {
    for (size_t i = 0; i < traced.size(); ++i) {
        const Aim& a = rays[traced[i]];
        Tally& t = tallies[a.pair];
        const double luminance = kWhiteEfficacy * photopic(records[i].value);
        const bool metSign = records[i].surfaceObject == signs[a.pair % signs.size()].sign.object;
        if (a.onSign) {
            ++t.signRays;
            if (metSign) ++t.signHits, t.signSum += luminance, t.signSquares += luminance * luminance;
        } else if (!metSign) {  // the band's rays that graze the sign's edge do not count
            ++t.backgroundRays, t.backgroundSum += luminance, t.backgroundSquares += luminance * luminance;
        }
    }
}



SightMeasure measure(const Observer& observer, const Sign& sign, const Tally& t, double opticalDepth, double coverage) {
    SightMeasure m;
    const dvec3 toEye = observer.eye - sign.centre;
    m.distance = glm::length(toEye);
    m.facing = facing(sign, observer.eye);
    m.signLuminance = mean(t.signSum, t.signHits);
    m.backgroundLuminance = mean(t.backgroundSum, t.backgroundRays);
    m.signError = standardError(t.signSum, t.signSquares, t.signHits);
    m.backgroundError = standardError(t.backgroundSum, t.backgroundSquares, t.backgroundRays);
    m.seenShare = t.signRays ? double(t.signHits) / t.signRays : 0;
    // A sign small beside its distance: its area times the cosine over the distance squared.
    m.solidAngle = m.facing ? sign.shape.area * glm::dot(sign.shape.normal, toEye) / std::pow(m.distance, 3) : 0;
    m.opticalDepth = opticalDepth;
    m.coverage = coverage;
    return m;
}

// One map per sign: `value(pair)` of each observer.
void writeMaps(const std::string& prefix, const ObserverGrid& g, const std::vector<Observer>& observers,
               const std::vector<SignTargets>& signs, const std::string& suffix, const std::string& what,
               const std::function<double(size_t)>& value, const std::string& command) {
    for (size_t s = 0; s < signs.size(); ++s) {
        std::vector<double> values;
        for (size_t ob = 0; ob < observers.size(); ++ob) values.push_back(value(ob * signs.size() + s));
        writeMap(prefix + "_" + signs[s].sign.name + suffix, g, observers, values,
                 what + " of sign " + signs[s].sign.name, command);
    }
}

int run(int argc, char** argv) {
    Options o;
    OptionTable table = makeTable(o);
    auto line = parseCommandLine(argc, argv, table, o.program, kUsage, "Multithreading\nReproducibleSampling\n");
    if (!line) return 0;
    checkRenderSettings(o.render);
    if (o.irradianceAtHit) throw UsageError("-i: a study traces the light that reaches the eye", kUsage);
    if (o.signs.empty()) throw UsageError("no signs (-S)", kUsage);
    if (o.rays < 1) throw UsageError("-vr: at least one ray", kUsage);
    if (o.passes < 1) throw UsageError("-vp: at least one pass", kUsage);
    if (!(o.criteria.minimumCoverage >= 0 && o.criteria.minimumCoverage <= 1))
        throw UsageError("-vc: a share, from 0 to 1", kUsage);
    if (!o.prefix.empty() && o.grid.empty()) throw UsageError("-o: maps need observers on a grid (-g)", kUsage);
    if (o.grid.empty() == o.waypoints.empty()) throw UsageError("give observers either on a grid (-g) or at waypoints (-wp)", kUsage);
    std::optional<ObserverGrid> grid;
    if (!o.grid.empty()) grid = makeGrid(o.grid[0], o.grid[1], o.grid[2], o.grid[3], o.grid[4]);
    std::vector<Observer> observers = loadObservers(o, grid);
    setSpectralSampling(o.render.sampling);
    Scene scene = loadScene(line->scene);
    std::vector<SignTargets> signs = loadSigns(o.signs, scene, o.rays);
    std::vector<double> instants = o.instants.empty() ? std::vector<double>{0} : o.instants;
    RenderScene renderScene(scene, o.render.materials);
    checkInstants(renderScene.smoke(), instants);
    for (const std::string& w : noDataWarnings(renderScene.smoke())) warn(w);
    Sequence sequence(scene, renderScene, o.render);
    const Integrator& integrator = sequence.integrator();
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(o.program.threads));
    tbb::global_control stack(tbb::global_control::thread_stack_size, size_t(64) << 20);

    const std::vector<Aim> rays = aims(observers, signs);
    const size_t pairs = observers.size() * signs.size();
    ProgressMeter progress("vismap", o.reportInterval);
    progress.start(long(rays.size() * instants.size()));  // the first passes: later ones are as few as need them
    Endurance endurance(pairs);
    const std::string command = commandLine(line->command);
    writeCsvHead();
    for (double t : instants) {
        std::vector<Tally> tallies(pairs);
        std::vector<SightMeasure> measures(pairs);
        std::vector<SightJudgement> judgements(pairs);
        std::vector<double> depths(pairs), coverage(pairs);  // once the first pass has prepared the smoke at t
        std::vector<bool> inPass(pairs, true);  // the sight lines the pass traces rays for
        std::vector<size_t> traced(rays.size());
        std::iota(traced.begin(), traced.end(), size_t(0));
        for (int pass = 0; !traced.empty(); ++pass) {
            std::vector<RayRecord> records(traced.size());
            sequence.run(traced.size(), t, [&](size_t i, WorkItem& item) {
                const Aim& a = rays[traced[i]];
                const dvec3 eye = observers[a.pair / signs.size()].eye;
                records[i] = integrator.trace({eye, glm::normalize(a.target - eye), pass * rays.size() + traced[i], t}, item);
                if (pass == 0) progress.advance(1, 1);
            });
            addTo(tallies, traced, rays, records, signs);
            for (size_t pair = 0; pair < pairs; ++pair) {
                if (!inPass[pair]) continue;
                const Sign& sign = signs[pair % signs.size()].sign;
                const Observer& observer = observers[pair / signs.size()];
                if (pass == 0) {
                    depths[pair] = integrator.quotedDepthBetween(observer.eye, sign.centre, t, o.quoted);
                    coverage[pair] = integrator.dataCoverageBetween(observer.eye, sign.centre, t);
                }
                measures[pair] = measure(observer, sign, tallies[pair], depths[pair], coverage[pair]);
                judgements[pair] = judge(measures[pair], sign.jinConstant, o.criteria);
                inPass[pair] = pass + 1 < o.passes && uncertain(judgements[pair], o.criteria);
            }
            std::erase_if(traced, [&](size_t i) { return !inPass[rays[i].pair]; });
        }
        std::vector<double> levels(pairs);
        for (size_t pair = 0; pair < pairs; ++pair) {
            const SightJudgement& j = judgements[pair];
            writeCsvRow(t, observers[pair / signs.size()], signs[pair % signs.size()].sign, measures[pair], j, o.quoted);
            levels[pair] = j.verdict == Verdict::Visible || j.verdict == Verdict::BelowThreshold ? j.visibilityLevel : 0;
            endurance.add(pair, t, j);
        }
        std::fflush(stdout);
        char suffix[64];
        std::snprintf(suffix, sizeof suffix, "_%g.hdr", t);
        if (o.prefix.empty()) continue;
        writeMaps(o.prefix, *grid, observers, signs, suffix,
                  "visibility level at t = " + std::to_string(t) + " s (0: hidden, behind or no data)",
                  [&](size_t pair) { return levels[pair]; }, command);
        if (std::any_of(coverage.begin(), coverage.end(), [](double c) { return c < 1; }))
            writeMaps(o.prefix, *grid, observers, signs, "_data" + std::string(suffix),
                      "share of the line with smoke data at t = " + std::to_string(t) + " s",
                      [&](size_t pair) { return coverage[pair]; }, command);
    }
    progress.finish();
    if (!o.prefix.empty()) {
        const std::string until = "the last instant (s) through which it stayed visible from the first (0: not then)";
        writeMaps(o.prefix, *grid, observers, signs, "_until.hdr", "by the light, " + until,
                  [&](size_t pair) { return endurance.light[pair]; }, command);
        writeMaps(o.prefix, *grid, observers, signs, "_jin_until.hdr", "by Jin's law, " + until,
                  [&](size_t pair) { return endurance.jin[pair]; }, command);
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return runReportingErrors([&] { return run(argc, argv); });
}
