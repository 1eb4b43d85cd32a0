// rpict: pictures of a scene from views, as Radiance's rpict (see man/rpict.1).
#include <tbb/global_control.h>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>

#include "integrator/render_options.h"
#include "medium/smoke.h"
#include "render/camera_path.h"
#include "render/frame_output.h"
#include "render/picture_options.h"
#include "render/picture_renderer.h"
#include "render/progress.h"
#include "render/sequence.h"
#include "scene/reader.h"
#include "util/header.h"
#include "view/view_options.h"

using namespace brume;

namespace {

const char* const kUsage = "usage: rpict [options] octree|scene.rad ... > picture.hdr\n";

struct Options {
    ProgramOptions program;
    RenderSettings render;
    PictureSettings picture;
    View view;
    double reportInterval = 0;
    int sequenceStart = 0;
    std::string output, depthOutput, cameraPath;
    double framesPerSecond = 0;
    bool exrFloat = false;

    Options() { usePictureDefaults(render); }
};

OptionTable makeTable(Options& o) {
    OptionTable t;
    addProgramOptions(t, o.program);
    addViewOptions(t, o.view);
    addPictureOptions(t, o.picture);
    addRenderOptions(t, o.render, o.picture.irradiance);
    addRealOption(t, "-t", o.reportInterval, "seconds between progress reports (0: none, or a live line on a terminal)");
    addIntOption(t, "-S", o.sequenceStart, "sequence: render a picture per view line on the standard input, numbered from this");
    t.add("-o", 1, "output file (pattern with %d for sequences; .exr: OpenEXR)", [&o](const auto& a) { o.output = a[0]; });
    t.add("-z", 1, "depth output file (floats per pixel; pattern with %d for sequences)",
          [&o](const auto& a) { o.depthOutput = a[0]; });
    t.add("-path", 1, "camera path: lines of time px py pz dx dy dz [ux uy uz]",
          [&o](const auto& a) { o.cameraPath = a[0]; });
    addRealOption(t, "-fps", o.framesPerSecond, "frames per second along -path (0: a frame per key)");
    t.add("-ef", 1, "OpenEXR pixels: h (half) or f (float)", [&o](const auto& a) {
        if (a[0] != "h" && a[0] != "f") throw Error("bad OpenEXR pixel type '" + a[0] + "' for -ef (h or f)");
        o.exrFloat = a[0] == "f";
    }, [&o] { return std::string(o.exrFloat ? "f" : "h"); });
    addColorOutputOptions(t, o.picture.color, false);
    t.addUnsupported("-r", 1, "recover from an interrupted picture");
    t.addUnsupported("-ro", 1, "recover into the same picture");
    t.addUnsupported("-P", 1, "persistent mode");
    t.addUnsupported("-PP", 1, "persistent mode");
    t.addAttached("-ap", "photon maps (not supported)",
                  [](const std::string&) { throw Error("photon maps (-ap) are not supported by Brume"); });
    t.addUnsupported("-am", 1, "photon search radius");
    return t;
}

// Radiance's rpict header, in its order: the octree's header, the command, SOFTWARE=, FRAME=, VIEW=,
// PIXASPECT=, CAPDATE=, GMT=, PRIMARIES= (FORMAT= is the writer's); Brume's SCENETIME= after PIXASPECT=.
// A later frame on the standard output starts at FRAME=, continuing the first frame's header, as Radiance's.
std::vector<std::string> headerFor(const Scene& scene, const std::vector<std::string>& command, const SequenceFrame& f,
                                   const PictureSettings& p, bool laterFrame) {
    std::vector<std::string> h;
    std::istringstream software(softwareAndDates());
    std::string line;
    std::getline(software, line);
    if (!laterFrame) {
        for (const std::string& l : scene.headerLines)
            if (l.rfind("FORMAT=", 0) != 0 && l != "#?RADIANCE") h.push_back(l);
        h.push_back(commandLine(command));
        h.push_back(line);
    }
    if (f.number > 0) h.push_back("FRAME=" + std::to_string(f.number));
    h.push_back("VIEW= " + f.view.options());
    char buf[64];
    if (p.pixelAspect != 1) {
        std::snprintf(buf, sizeof buf, "PIXASPECT=%f", p.pixelAspect);
        h.push_back(buf);
    }
    if (f.time) {
        std::snprintf(buf, sizeof buf, "SCENETIME= %.10g", *f.time);
        h.push_back(buf);
    }
    while (std::getline(software, line)) h.push_back(line);  // CAPDATE=, GMT=
    // Radiance's rpict names the primaries of every RGB picture, its own included.
    if (p.color.kind == ColorOutput::Kind::Rgb) h.push_back(primariesLine(p.color.primaries));
    return h;
}

class Rpict {
public:
    Rpict(const Options& o, const Scene& scene, std::vector<std::string> command)
        : o_(o), scene_(scene), renderScene_(scene, o.render.materials), command_(std::move(command)),
          progress_("rpict", o.reportInterval), sequence_(scene, renderScene_, o.render) {
        for (const std::string& w : noDataWarnings(renderScene_.smoke())) warn(w);
    }

    void render(const SequenceFrame& f) {
        f.view.validate();
        std::string picturePath = o_.output.empty() ? "" : frameFileName(o_.output, f.number);
        if (!picturePath.empty() && !claimFile(picturePath)) {
            if (namesFrames(o_.output)) return;  // another process has (or had) this frame
            throw Error("cannot open output file \"" + picturePath + "\": it exists");
        }
        try {
            renderTo(f, picturePath);
        } catch (...) {
            if (!picturePath.empty()) std::remove(picturePath.c_str());  // release the claim
            throw;
        }
    }

private:
    void renderTo(const SequenceFrame& f, const std::string& picturePath) {
        PictureSettings p = o_.picture;
        p.depth = !o_.depthOutput.empty();
        p.drawSources = o_.render.directVisible && p.aperture == 0;
        fitPictureResolution(f.view, p);
        RenderedPicture r = sequence_.render(f, p, &progress_);
        if (sequence_.cache() && o_.reportInterval > 0)
            std::fprintf(stderr, "rpict: irradiance cache: %s\n", sequence_.cache()->summary().c_str());
        if (sequence_.volumes() && sequence_.volumes()->size() > 0 && o_.reportInterval > 0)
            std::fprintf(stderr, "rpict: volume cache: %s\n", sequence_.volumes()->summary().c_str());
        bool laterFrame = picturePath.empty() && framesOnOutput_++ > 0;
        r.picture.header = headerFor(scene_, command_, f, p, laterFrame);
        if (picturePath.empty()) writeRadiancePicture(std::cout, r.picture, laterFrame);
        else writePictureFile(picturePath, r.picture, o_.exrFloat, r.spectra.values.empty() ? nullptr : &r.spectra);
        if (p.depth) writeDepthFile(frameFileName(o_.depthOutput, f.number), r.depth);
    }

    const Options& o_;
    const Scene& scene_;
    RenderScene renderScene_;
    std::vector<std::string> command_;
    ProgressMeter progress_;
    Sequence sequence_;
    int framesOnOutput_ = 0;
};

int run(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    Options o;
    OptionTable table = makeTable(o);
    auto line = parseCommandLine(argc, argv, table, o.program, kUsage, "Multithreading\nReproducibleSampling\nDepthOfField\n");
    if (!line) return 0;
    checkRenderSettings(o.render);
    setSpectralSampling(o.render.sampling);
    if (o.render.ambientBounces > 0 && o.render.ambientAccuracy == 0 && o.render.ambientDivisions > 64)
        warn("-aa 0: -ab " + std::to_string(o.render.ambientBounces) + " path-traces " +
             std::to_string(o.render.ambientDivisions) + " paths (-ad) from every pixel traced, a long run; "
             "the irradiance cache (-aa > 0) or -ad 16 to 64 give a picture much sooner");
    if (o.sequenceStart < 0) throw Error("bad sequence start " + std::to_string(o.sequenceStart));
    if (o.sequenceStart > 0 && !o.cameraPath.empty()) throw Error("-S and -path are exclusive");
    if (o.sequenceStart > 0 && std::find(line->scene.begin(), line->scene.end(), "-") != line->scene.end())
        throw Error("the scene cannot be read from the standard input with -S (the views are)");
    bool sequence = o.sequenceStart > 0 || !o.cameraPath.empty();
    if (!sequence && !o.output.empty() && namesFrames(o.output))
        throw Error("output pattern '" + o.output + "' names frames, but there is no sequence (-S or -path)");
    o.view.validate();
    std::optional<CameraPath> path;
    if (!o.cameraPath.empty()) path = CameraPath::read(o.cameraPath, o.view.vu);

    Scene scene = loadScene(line->scene);
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, size_t(o.program.threads));
    tbb::global_control stack(tbb::global_control::thread_stack_size, size_t(64) << 20);  // deep ray trees
    Rpict rpict(o, scene, line->command);
    Frames frames = path                  ? Frames::along(*path, o.view, o.framesPerSecond, std::max(o.sequenceStart, 1))
                    : o.sequenceStart > 0 ? Frames::viewLines(std::cin, o.view, o.sequenceStart, o.render.time)
                                          : Frames::single(o.view, o.render.time);
    while (std::optional<SequenceFrame> f = frames.next()) rpict.render(*f);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return runReportingErrors([&] { return run(argc, argv); });
}
