// xform's command line (man/xform.1): options, then a transform, then files. Arrays (-a) and argument
// files (-f) stand for several plain runs, each writing its own header, as Radiance's xform expands them
// by calling itself with rewritten arguments: "xform -a 2 -t 1 0 0 f" is "xform -n a0 -i 0 -t 1 0 0 f"
// then "xform -n a1 -i 1 -t 1 0 0 f".
#pragma once
#include <functional>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "scene/transform_text.h"

namespace brume {

// One plain run (argv[0] first, no -a or -f left), or a comment or blank line of an argument file, which
// goes to the output as it is.
struct XformRun {
    std::vector<std::string> args;
    std::string echo;  // when args is empty
};

class XformExpansion {
public:
    using Visit = std::function<void(const XformRun&)>;

    // Calls `visit` with each run that `argv` stands for, in order. Argument files are read once and
    // remembered, so that a second pass sees the same runs. Throws Error on a missing -a count, or an
    // argument file that cannot be read, holds no arguments or names itself.
    void forEachRun(const std::vector<std::string>& argv, const Visit& visit);
    // Whether an argument file came from the standard input (-f -), which then holds no scene.
    bool readStandardInput() const { return files_.contains("-"); }

private:
    void argumentFile(const std::vector<std::string>& argv, size_t at, const Visit& visit);
    void array(const std::vector<std::string>& argv, size_t at, const Visit& visit);
    const std::vector<std::string>& lines(const std::string& file);

    std::map<std::string, std::vector<std::string>> files_;
    std::set<std::string> expanding_;  // argument files being expanded, which a line may not name again
};

struct XformCommand {
    SceneTransform transform;
    std::vector<std::string> files;  // none: the standard input
    std::string header;              // "# xform -n a0 -i 0 -t 1 0 0": the command up to its files
};

// Reads a plain run as Radiance's xform does: options -c -e -I -m -n, the transform, the files. Throws
// Error ("command line error at '-t'") for a word starting with '-' where a file should be, which is how
// a transform with a bad or missing value shows.
XformCommand parseXformCommand(const std::vector<std::string>& args);

}  // namespace brume
