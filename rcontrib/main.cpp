// rcontrib: each light source's contribution to the values along rays read from standard input, binned by
// direction, as Radiance's rcontrib (see man/rcontrib.1). Its run is lib/contrib's.
#include <iostream>

#include "contrib/contribution_run.h"
#include "io/ray_reader.h"

using namespace brume;

namespace {

const char* const kUsage =
    "usage: rcontrib [options] [-e expr][-f file][-p a=v,...][-b binv][-bn N] {-m mod | -M file} ... octree|scene.rad ... < rays\n";

int run(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    ContributionRun o;
    OptionTable table = contributionOptions(o);
    auto line = parseContributionCommandLine(argc, argv, table, o.program, kUsage, "Multithreading\nAccumulation\n");
    if (!line) return 0;
    RayReader reader(std::cin, o.inFormat, "(stdin)");
    runContributions(o, line->scene, line->command, [&](std::array<double, 6>& r) { return reader.next(r); });
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return runReportingErrors([&] { return run(argc, argv); });
}
