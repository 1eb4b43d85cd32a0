// xform: transform a Radiance scene description, as Radiance's xform (see man/xform.1).
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include "scene/raypath.h"
#include "scene/xform_command.h"
#include "util/error.h"

using namespace brume;
namespace fs = std::filesystem;

namespace {

// The standard input, read once: an array transforms it once per copy.
const std::string& standardInput() {
    static const std::string text(std::istreambuf_iterator<char>(std::cin), {});
    return text;
}

// Commands in a file run in the file's directory, as with Radiance's xform, so that a file saying
// "!xform part.rad" finds part.rad beside it wherever it is transformed from.
class WorkingDirectory {
public:
    explicit WorkingDirectory(const fs::path& dir) : previous_(fs::current_path()) {
        if (!dir.empty()) fs::current_path(dir);
    }
    ~WorkingDirectory() {
        std::error_code ignored;
        fs::current_path(previous_, ignored);
    }

private:
    fs::path previous_;
};

void transformFile(const std::string& name, const SceneTransform& how) {
    std::string found = findOnRayPath(name);
    if (found.empty()) throw Error(SourceLocation{name}, "cannot find file along RAYPATH");
    if (found.starts_with("./")) found.erase(0, 2);
    std::ifstream in(found, std::ios::binary);
    if (!in) throw Error(SourceLocation{found}, "cannot open file");
    WorkingDirectory here(how.expandCommands ? fs::path(found).parent_path() : fs::path());
    transformSceneText(in, found, how, std::cout);
}

void transform(const XformCommand& command) {
    std::cout << command.header << '\n';
    if (command.files.empty()) {
        std::istringstream in(standardInput());
        transformSceneText(in, "standard input", command.transform, std::cout);
    }
    for (const std::string& file : command.files) transformFile(file, command.transform);
}

int run(int argc, char** argv) {
    setProgramName(argv[0]);
    std::vector<std::string> args(argv, argv + argc);
    XformExpansion runs;
    // Every run's options are read before anything is written: a bad transform leaves no output.
    bool scenesFromStandardInput = false;
    runs.forEachRun(args, [&](const XformRun& run) {
        if (!run.args.empty()) scenesFromStandardInput |= parseXformCommand(run.args).files.empty();
    });
    if (scenesFromStandardInput && runs.readStandardInput()) throw Error("cannot use stdin more than once");
    runs.forEachRun(args, [](const XformRun& run) {
        if (run.args.empty()) std::cout << run.echo << '\n';
        else transform(parseXformCommand(run.args));
    });
    if (!std::cout.flush()) throw std::runtime_error("write error");
    return 0;
}

}  // namespace

int main(int argc, char** argv) { return runReportingErrors([&] { return run(argc, argv); }); }
