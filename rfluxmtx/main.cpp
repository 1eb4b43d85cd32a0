// rfluxmtx: flux transfer coefficients from rays on the standard input or the bins of a sender surface's
// hemisphere to the receivers of a file, each binned over the hemisphere its "#@rfluxmtx" line names, as
// Radiance's rfluxmtx (see man/rfluxmtx.1): rcontrib's run (lib/contrib) with the receivers' modifiers and bins,
// a row for each sender bin.
#include <iostream>
#include <optional>

#include "contrib/contribution_run.h"
#include "contrib/receivers.h"
#include "contrib/senders.h"
#include "integrator/settings.h"
#include "io/ray_reader.h"
#include "util/error.h"
#include "util/header.h"

using namespace brume;

namespace {

// Rays a sender's bin averages where -c does not say (Radiance's default).
constexpr int kSenderRays = 10000;

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

// The sender's rays, bin after bin, -c of each.
struct SenderRays {
    const Sender& sender;
    int perBin;
    uint64_t seed;
    int bin = 0, index = 0;

    bool operator()(std::array<double, 6>& ray) {
        if (bin == sender.bins()) return false;
        ray = sender.ray(bin, uint32_t(index), seed);
        if (++index == perBin) index = 0, ++bin;
        return true;
    }
};

int run(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    ContributionRun o;
    o.accumulate = 0;  // unset: 1 ray a record from the standard input, 10000 from a sender
    bool verbose = false;
    OptionTable table = contributionOptions(o);
    table.addBool("-v", verbose, "verbose: say the rcontrib command it runs");
    auto line = parseContributionCommandLine(argc, argv, table, o.program, kUsage, "Multithreading\n");
    if (!line) return 0;
    const std::vector<std::string>& operands = line->scene;
    if (operands.size() < 2) throw UsageError("missing receiver file", kUsage);
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
    std::optional<Sender> sender;
    if (operands[0] != "-") {
        if (o.irradiance || o.irradianceAtHit) throw Error("-i, -I supported for pass-through only");
        sender.emplace(operands[0]);
        o.yres = sender->bins(), o.xres = 0;
    }
    std::vector<std::string> rcontrib{"rcontrib"};
    rcontrib.insert(rcontrib.end(), line->command.begin() + 1, line->command.end());
    std::erase(rcontrib, std::string("-v"));
    // A sender's rows: -c rays each (10000 unless given), one per bin (-y), as Radiance's adds them.
    if (o.accumulate == 0) {
        o.accumulate = sender ? kSenderRays : 1;
        if (sender) rcontrib.insert(rcontrib.end(), {"-c", std::to_string(o.accumulate)});
    }
    for (const FluxReceiver& r : readReceivers(operands[1])) addReceiver(r, o, rcontrib);
    if (sender) rcontrib.insert(rcontrib.end(), {"-y", std::to_string(sender->bins())});
    rcontrib.insert(rcontrib.end(), scene.begin(), scene.end());
    if (verbose) {
        std::cerr << programName() << ": running: " << shellLine(rcontrib) << "\n";
        if (sender)
            std::cerr << programName() << ": sampling " << sender->bins() << " directions"
                      << (sender->surfaces() > 1 ? " (" + std::to_string(sender->surfaces()) + " elements)" : "") << "\n";
    }
    std::vector<std::string> command = line->command;
    command.insert(command.end(), operands.begin(), operands.end());
    if (sender) {
        runContributions(o, scene, command, SenderRays{*sender, o.accumulate, runSeed(o.render)});
    } else {
        RayReader reader(std::cin, o.inFormat, "(stdin)");
        runContributions(o, scene, command, [&](std::array<double, 6>& r) { return reader.next(r); });
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return runReportingErrors([&] { return run(argc, argv); });
}
