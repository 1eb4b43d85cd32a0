// rfluxmtx: daylight coefficients from rays (or, not yet, sender surfaces) to the receivers of a file, each
// binned over the hemisphere its "#@rfluxmtx" line names, as Radiance's rfluxmtx (see man/rfluxmtx.1):
// rcontrib's run (lib/contrib) with the receivers' modifiers and bins.
#include <iostream>

#include "contrib/contribution_run.h"
#include "contrib/receivers.h"
#include "util/error.h"
#include "util/header.h"

using namespace brume;

namespace {

const char* const kUsage =
    "usage: rfluxmtx [-v][rcontrib options] { sender.rad | - } receiver.rad [-i system.oct] [system.rad ...]\n";

// Words as a shell takes them: quoted where they hold anything but letters, digits and _ . / = , + : -.
std::string shellLine(const std::vector<std::string>& words) {
    std::string line;
    for (const std::string& w : words) {
        bool plain = !w.empty() && w.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                       "0123456789_./=,+:-") == std::string::npos;
        line += (line.empty() ? "" : " ") + (plain ? w : "'" + w + "'");
    }
    return line;
}

int run(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    ContributionRun o;
    bool verbose = false;
    OptionTable table = contributionOptions(o);
    table.addBool("-v", verbose, "verbose: say the rcontrib command it runs");
    auto line = parseContributionCommandLine(argc, argv, table, o.program, kUsage, "Multithreading\n");
    if (!line) return 0;
    const std::vector<std::string>& operands = line->scene;
    if (operands.size() < 2) throw UsageError("missing receiver file", kUsage);
    if (operands[0] != "-")
        throw Error("sender surfaces are not supported yet: give '-' and the rays on the standard input");
    std::vector<std::string> scene;
    for (size_t i = 2; i < operands.size(); ++i) {
        if (operands[i] == "-i") {
            if (++i == operands.size()) throw UsageError("-i: missing system octree", kUsage);
        } else if (operands[i][0] == '-') {
            throw UsageError("option " + operands[i] + " after the sender and receiver", kUsage);
        }
        scene.push_back(operands[i]);
    }
    scene.push_back(operands[1]);
    std::vector<std::string> rcontrib{"rcontrib"};
    rcontrib.insert(rcontrib.end(), line->command.begin() + 1, line->command.end());
    std::erase(rcontrib, std::string("-v"));
    for (const Receiver& r : readReceivers(operands[1])) addReceiver(r, o, rcontrib);
    rcontrib.insert(rcontrib.end(), scene.begin(), scene.end());
    if (verbose) std::cerr << programName() << ": running: " << shellLine(rcontrib) << "\n";
    std::vector<std::string> command = line->command;
    command.insert(command.end(), operands.begin(), operands.end());
    runContributions(o, scene, command, std::cin);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return runReportingErrors([&] { return run(argc, argv); });
}
