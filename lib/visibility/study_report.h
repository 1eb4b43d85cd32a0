// What a visibility study writes. On the standard output, a CSV of every instant, observer and sign: numbers
// only, an empty field where there is none (no visibility level where the sign is hidden or seen from behind, no
// luminances from behind, no Jin's distance in clear air). With a prefix: per sign and instant, maps over the
// grid (Radiance pictures of one value a cell); and at the end, the maps of how long each sign (and any sign:
// prefix_any_until.hdr, prefix_any_jin_until.hdr) stayed visible, prefix_lost.csv (when each sight line lost its sign, by each criterion, interpolated or
// bracketed: Endurance), prefix_summary.csv (per instant and sign, the share of observers who see it) and
// prefix.json (the criteria, the signs, the smoke, the command and the version: what the numbers mean).
#pragma once
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include "visibility/endurance.h"

namespace brume {

struct ReportSettings {
    std::string prefix;                 // none: the CSV only
    std::optional<ObserverGrid> grid;   // maps need one
    std::string command;                // the command line, for headers
    std::vector<double> instants;
    std::vector<SmokeDescription> smoke;  // what the study saw the signs through
};

class StudyReport {
public:
    // Writes the CSV's head to `csv`.
    StudyReport(const VisibilityStudy& study, std::FILE* csv, ReportSettings settings);
    // An instant's rows and maps, and its summary's lines.
    void instant(double time, const std::vector<SightLine>& lines);
    // The rest: the maps of how long signs stayed visible, the losses, the summary and the JSON.
    void finish(const Endurance& endurance);

private:
    void writeRow(double time, size_t line, const SightLine& s) const;
    void writeMap(const std::string& path, const std::string& what, const std::vector<double>& values) const;
    void writeMaps(const std::string& suffix, const std::string& what, const std::vector<double>& values) const;
    void writeLosses(const Endurance& endurance) const;
    void writeJson() const;

    const VisibilityStudy& study_;
    std::FILE* csv_;
    ReportSettings settings_;
    std::string summary_;  // its rows so far
};

}  // namespace brume
