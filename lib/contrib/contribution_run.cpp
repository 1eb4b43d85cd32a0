#include "contrib/contribution_run.h"

#include <tbb/enumerable_thread_specific.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <fstream>

#include "contrib/contribution_output.h"
#include "contrib/contribution_tally.h"
#include "io/ray_reader.h"
#include "render/sequence.h"
#include "render/shared_bounces.h"
#include "scene/reader.h"
#include "spectrum/color_output.h"
#include "util/error.h"
#include "util/header.h"

namespace brume {

void ContributionRun::addModifier(const std::string& name) {
    ModifierRequest r = next;
    r.name = name;
    modifiers.push_back(r);
}

namespace {

// What the option table takes a -f before a file name for.
const char* const kFunctionFileOption = "--function-file";

// -M: modifier names, separated by white space.
void addModifierFile(ContributionRun& o, const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error(path + ": cannot open modifier file");
    for (std::string name; in >> name;) o.addModifier(name);
}

void setFormats(ContributionRun& o, const std::string& v) {
    if (v == "o" || v == "o+" || v == "o-") {
        o.overwrite = v != "o-";
        return;
    }
    // RGBE (c) for the output only, as pictures: rays come as numbers.
    if (v.empty() || v.size() > 2 || std::string("afd").find(v[0]) == std::string::npos ||
        (v.size() == 2 && std::string("afdc").find(v[1]) == std::string::npos))
        throw Error("Illegal i/o format: -f" + v);
    o.inFormat = v[0];
    o.outFormat = v.size() == 2 ? v[1] : v[0];
}

}  // namespace

std::optional<CommandLine> parseContributionCommandLine(int argc, char** argv, const OptionTable& table,
                                                        const ProgramOptions& program, const std::string& usage,
                                                        const std::string& features) {
    std::vector<std::string> words(argv + 1, argv + argc);
    expandResponseFiles(words);
    std::vector<char*> args{argv[0]};
    for (std::string& w : words) {
        if (w == "-f") w = kFunctionFileOption;
        args.push_back(w.data());
    }
    auto line = parseCommandLine(int(args.size()), args.data(), table, program, usage, features);
    if (line)
        for (std::string& w : line->command)
            if (w == kFunctionFileOption) w = "-f";
    return line;
}

OptionTable contributionOptions(ContributionRun& o) {
    OptionTable t;
    addProgramOptions(t, o.program);
    t.remove("-e");
    addRenderOptions(t, o.render, o.irradianceAtHit);
    t.add("-x", 1, "x resolution (records per row)", [&o](const auto& a) { o.xres = toInt("-x", a[0]); });
    t.add("-y", 1, "y resolution (rows: records to compute)", [&o](const auto& a) { o.yres = toInt("-y", a[0]); });
    t.addBool("-h", o.header, "output header");
    t.addBool("-I", o.irradiance, "irradiance at the ray origin, the direction being the surface normal");
    t.addBool("-V", o.values, "contributions (coefficient times the source's radiance) rather than coefficients");
    addShareBouncesOption(t, o.shareBounces);
    t.add("-c", 1, "rays accumulated (averaged) per record", [&o](const auto& a) {
        o.accumulate = toInt("-c", a[0]);
        if (o.accumulate < 1) throw Error("-c: Brume accumulates one ray or more per record (not -c 0)");
    });
    t.add("-e", 1, "expression (definitions for the bins)", [&o](const auto& a) {
        o.definitions.push_back({CalDefinition::Kind::Expression, a[0]});
    });
    t.add(kFunctionFileOption, 1, "function file (-f file)", [&o](const auto& a) {
        o.definitions.push_back({CalDefinition::Kind::File, a[0]});
    });
    t.addAttached("-f", "-f file: function file; -f[io]: formats a, f, d; -fo: overwrite outputs",
                  [&o](const std::string& v) { setFormats(o, v); });
    t.add("-o", 1, "output file pattern (%s modifier, %d bin) of the modifiers that follow",
          [&o](const auto& a) { o.next.output = a[0]; });
    t.add("-p", 1, "parameters (a=1,b=2) of the modifiers that follow", [&o](const auto& a) { o.next.parameters = a[0]; });
    t.add("-b", 1, "bin expression of the modifiers that follow", [&o](const auto& a) { o.next.bin = a[0]; });
    t.add("-bn", 1, "number of bins of the modifiers that follow", [&o](const auto& a) { o.next.binCount = a[0]; });
    t.add("-m", 1, "modifier whose contributions are told", [&o](const auto& a) { o.addModifier(a[0]); });
    t.add("-M", 1, "file of modifiers whose contributions are told", [&o](const auto& a) { addModifierFile(o, a[0]); });
    t.addUnsupported("-r", 0, "recover");
    t.addUnsupported("-ap", 1, "photon maps");
    return t;
}

namespace {

// Radiance overrides these in rcontrib: cached values and guessed shadows cannot be told apart by source.
void overrideSettings(RenderSettings& s) {
    s.ambientAccuracy = 0;
    s.ambientSupersamples = 0;
    s.directThreshold = 0;
}

struct RecordSource {
    const RayStream& rays;
    long limit;  // records to read, 0: until the end
    long read = 0;
};

// Up to `max` records of `per` rays each; false at the end of the input.
bool nextRecords(RecordSource& src, int per, size_t max, std::vector<InputRay>& rays) {
    rays.clear();
    std::array<double, 6> r;
    while (rays.size() < max * per && (src.limit == 0 || src.read < src.limit)) {
        if (!src.rays(r)) {
            if (rays.size() % per) throw Error("(stdin): input ends within a record (-c " + std::to_string(per) + ")");
            if (src.limit && src.read < src.limit)
                warn("input ended after " + std::to_string(src.read) + " of " + std::to_string(src.limit) + " records");
            break;
        }
        rays.push_back(inputRay(r));
        if (rays.size() % per == 0) ++src.read;
    }
    return !rays.empty();
}

OutputSettings outputSettings(const ContributionRun& o, const Scene& scene, const std::vector<std::string>& command) {
    OutputSettings out;
    out.format = o.outFormat;
    out.header = o.header;
    out.overwrite = o.overwrite;
    out.xres = o.xres, out.yres = o.yres;
    out.channels = Spectrum(0.f).size();
    if (out.channels > 3) out.colorLines = ColorOutput{ColorOutput::Kind::Spectral}.headerLines();
    out.headerLines = scene.headerLines;
    std::erase_if(out.headerLines,
                  [](const std::string& l) { return l.rfind("FORMAT=", 0) == 0 || l.rfind("#?", 0) == 0; });
    out.headerLines.push_back(commandLine(command));
    return out;
}

}  // namespace

void runContributions(ContributionRun o, const std::vector<std::string>& sceneFiles,
                      const std::vector<std::string>& command, const RayStream& input) {
    if (o.modifiers.empty()) throw Error("no modifiers given (-m or -M)");
    if (o.irradiance && o.irradianceAtHit) throw Error("-I and -i are exclusive");
    overrideSettings(o.render);
    checkRenderSettings(o.render);
    setSpectralSampling(o.render.sampling);
    Scene scene = loadScene(sceneFiles);
    RenderScene renderScene(scene, o.render.materials);
    if (!renderScene.smoke().empty() || renderScene.hasMists() || !o.render.medium.clear())
        throw Error("participating media (smoke, mist, -me) are not supported by rcontrib yet");
    ModifierBins bins(scene, renderScene, o.definitions, o.modifiers);
    Sequence sequence(scene, renderScene, o.render);
    const Integrator& integrator = sequence.integrator();
    const double instant = o.render.time.value_or(0);
    OutputSettings settings = outputSettings(o, scene, command);
    ContributionOutput output(bins, settings);

    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(o.program.threads));
    tbb::global_control stack(tbb::global_control::thread_stack_size, size_t(64) << 20);
    tbb::enumerable_thread_specific<ContributionTally> tallies(
        [&] { return ContributionTally(bins, o.values, settings.channels); });
    RecordSource source{input, o.yres > 0 ? long(std::max(o.xres, 1)) * o.yres : 0};
    const size_t width = size_t(bins.columns()) * settings.channels;
    std::optional<SharedBounces> pool;
    if (o.shareBounces > 0 && sharesBounces(renderScene, o.render))
        pool.emplace(o.shareBounces, continuationsPerCell(o.render.ambientDivisions), settings.channels, width,
                     renderScene.geometry().origin());
    size_t batch = std::clamp<size_t>((size_t(64) << 20) / (width * sizeof(double)), 1, kRayBatchSize);
    // Shared bounces keep each first bounce of a batch until its cells are traced.
    if (pool) {
        size_t bouncesPerRecord = size_t(o.accumulate) * size_t(std::max(o.render.ambientDivisions, 1));
        batch = std::clamp<size_t>(kSharedBouncesPerBatch / bouncesPerRecord, 1, batch);
    }
    // A cell's continuations, their contributions told to a tally.
    SharedBounces::CellTracer cellTracer = [&](const std::vector<Continuation>& paths, WorkItem& item,
                                               std::vector<double>& sums) {
        ContributionTally& tally = tallies.local();
        tally.clear();
        WorkItem told{item.scratch, nullptr, &tally};
        for (const Continuation& p : paths) integrator.continueBounce(*p.bounce, p.dir, instant, p.weightScale, p.index, told);
        sums = tally.sums();
    };
    std::vector<InputRay> rays;
    std::vector<std::vector<double>> records;
    uint64_t first = 0;
    while (nextRecords(source, o.accumulate, batch, rays)) {
        size_t count = rays.size() / o.accumulate;
        records.assign(count, std::vector<double>(width, 0.0));
        if (pool) pool->reset(count);
        sequence.run(count, instant, [&](size_t i, WorkItem& item) {
            ContributionTally& tally = tallies.local();
            tally.clear();
            WorkItem told{item.scratch, nullptr, &tally, pool ? &pool->of(i) : nullptr};
            for (int k = 0; k < o.accumulate; ++k) {
                const InputRay& ray = rays[i * o.accumulate + k];
                if (ray.zero) continue;
                RayQuery q{ray.org, ray.dir, first + i * o.accumulate + k, instant};
                if (o.irradiance) integrator.irradiance(q, told);
                else if (o.irradianceAtHit) integrator.irradianceAtHit(q, told);
                else integrator.trace(q, told);
            }
            const std::vector<double>& sums = tally.sums();
            for (size_t c = 0; c < width; ++c) records[i][c] = sums[c] / o.accumulate;
        });
        if (pool) pool->resolve(sequence, instant, first, cellTracer, 1.0 / o.accumulate, records);
        for (const std::vector<double>& r : records) output.write(r);
        output.flush();
        first += rays.size();
    }
    long ignored = 0;
    for (const ContributionTally& t : tallies) ignored += t.outOfRange();
    if (ignored > 0) warn(std::to_string(ignored) + " contributions fell past their modifier's last bin and were ignored");
    output.finish();
}

}  // namespace brume
