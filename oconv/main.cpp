// oconv: a Radiance octree of scene descriptions, as Radiance's oconv makes it (see man/oconv.1).
#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "scene/octree.h"
#include "scene/placed_files.h"
#include "scene/reader.h"
#include "util/error.h"
#include "util/header.h"
#include "world/octree_build.h"

using namespace brume;

namespace {

const char* const kUsage =
    "usage: oconv [-f][-w][-r maxres][-n objlim][-b xmin ymin zmin size | -i octree] file.rad .. > file.oct\n";

struct Command {
    bool frozen = false, quiet = false;
    OctreeBuildOptions build;
    std::string base;                // -i: the octree added to
    std::vector<std::string> files;  // "-" is the standard input
};

double number(const std::vector<std::string>& args, size_t at, const std::string& option) {
    if (at >= args.size()) throw UsageError("missing value for " + option, kUsage);
    try {
        size_t used = 0;
        double x = std::stod(args[at], &used);
        if (used == args[at].size() && std::isfinite(x)) return x;
    } catch (const std::exception&) {
    }
    throw UsageError("bad value for " + option + ": '" + args[at] + "'", kUsage);
}

int positive(double x, const std::string& option) {
    if (x < 1 || x > 1 << 30 || x != double(long(x))) throw UsageError(option + " needs a positive integer", kUsage);
    return int(x);
}

Command parse(const std::vector<std::string>& args) {
    Command c;
    size_t i = 1;
    for (; i < args.size() && args[i].size() > 1 && args[i][0] == '-'; ++i) {
        const std::string& a = args[i];
        if (a == "-f") {
            c.frozen = true;
        } else if (a == "-w") {
            c.quiet = true;
        } else if (a == "-r") {
            c.build.resolution = positive(number(args, ++i, a), a);
        } else if (a == "-n") {
            c.build.objectLimit = size_t(positive(number(args, ++i, a), a));
        } else if (a == "-b") {
            OctreeCube cube;
            for (double& x : cube.origin) x = number(args, ++i, a) - kOctreeMargin;
            cube.size = number(args, ++i, a) + 2 * kOctreeMargin;
            if (!(cube.size > 2 * kOctreeMargin)) throw UsageError("-b needs a positive size", kUsage);
            c.build.cube = cube;
        } else if (a == "-i") {
            if (++i >= args.size()) throw UsageError("missing value for -i", kUsage);
            c.base = args[i];
        } else {
            throw UsageError("unknown option: '" + a + "'", kUsage);
        }
    }
    c.files.assign(args.begin() + long(i), args.end());
    if (c.files.empty() && c.base.empty()) throw UsageError("no scene files", kUsage);
    if (!c.base.empty() && c.build.cube) throw UsageError("only one of '-b' or '-i'", kUsage);
    return c;
}

// The octree -i adds to, as Radiance's oconv takes it: its objects (a normal octree's files read again), its
// cube (the new objects must fit in it), its header (copied before this command's line) and its files (listed
// first, unless it is frozen: then so is the new one).
struct Base {
    std::vector<std::string> headerLines{"#?RADIANCE"}, files;
    bool frozen = false;
};

Base readBase(const Command& command, Scene& scene, OctreeBuildOptions& build) {
    Base base;
    if (command.base.empty()) return base;
    readOctreeFile(scene, command.base, &base.files);
    base.headerLines = scene.headerLines;
    build.cube = scene.cube;
    base.frozen = base.files.empty();
    if (base.frozen && !command.frozen && !command.quiet) warn(command.base + ": frozen octree: so is the new one");
    return base;
}

int run(int argc, char** argv) {
    std::vector<std::string> args(argv, argv + argc);
    Command command = parse(args);
    Scene scene;
    Base base = readBase(command, scene, command.build);
    for (const std::string& file : command.files) readSceneFile(scene, file);
    size_t count = scene.objects.size();
    loadPlacedFiles(scene);
    BuiltOctree built = buildOctree(scene, count, command.build);
    if (built.overflowObject >= 0 && !command.quiet)
        warn("set overflow: more than " + std::to_string(kMaxOctreeSet) +
             " objects meet one cube that is divided no further (first left out: " +
             scene.objects[built.overflowObject].type + " \"" + scene.objects[built.overflowObject].name +
             "\"); Radiance's programs will miss them there");
    bool fromInput = false;
    for (const std::string& file : command.files) fromInput = fromInput || file == "-";
    base.headerLines.push_back(commandLine(args));
    OctreeContents octree{base.headerLines, built.cube, {}, &scene, count, std::move(built.nodes)};
    if (!command.frozen && !fromInput && !base.frozen) {
        octree.files = base.files;
        octree.files.insert(octree.files.end(), command.files.begin(), command.files.end());
    }
    // Written whole once made, so that an error leaves no half octree behind.
    std::ostringstream bytes;
    writeOctree(bytes, octree);
    std::string data = bytes.str();
    if (std::fwrite(data.data(), 1, data.size(), stdout) != data.size() || std::fflush(stdout) != 0)
        throw Error("write error on the standard output");
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    setProgramName(argv[0]);
    return runReportingErrors([&] { return run(argc, argv); });
}
