// Where rcontrib's records go, as Radiance's rcontrib writes them: each modifier's bins to the files its -o
// pattern names (%s: the modifier, %d: the bin, so a file per modifier or per bin), or without one to the
// standard output, those modifiers' bins on one row; each stream with its header (the command, NCOMP, MODIFIER=
// and BIN= where one, NROWS= when -y says how many, -y times -x, NCOLS= unless it is a picture, FORMAT=); a
// stream of one bin with -x and -y is a picture, its resolution line after the header. ASCII elements are
// each component "%e" and a tab; binary ones native floats or doubles, or (-fc) Radiance's common-exponent
// bytes (RGBE; spectra's N mantissas and an exponent). Files are written beside their names and renamed into
// place when complete: a run that fails leaves none half-written (and an existing file is refused unless -fo).
#pragma once
#include <cstdio>
#include <string>
#include <vector>

#include "contrib/modifier_bins.h"

namespace brume {

struct OutputSettings {
    char format = 'a';         // a, f, d, c
    bool header = true;        // -h
    bool overwrite = false;    // -fo
    int xres = 0, yres = 0;    // -x, -y: NROWS = yres × xres (or yres), 0: not said
    int channels = 3;          // NCOMP
    std::vector<std::string> colorLines;   // after NCOMP: WAVELENGTH_SPLITS= for spectral channels
    std::vector<std::string> headerLines;  // the scene's header and the command line, without "#?RADIANCE"
};

class ContributionOutput {
public:
    // Opens every stream and writes its header. Throws Error for an -o pattern other than %s, %d and %%
    // conversions, or a file that exists (without -fo) or cannot be made.
    ContributionOutput(const ModifierBins& bins, const OutputSettings& settings);
    ~ContributionOutput();
    ContributionOutput(const ContributionOutput&) = delete;
    ContributionOutput& operator=(const ContributionOutput&) = delete;

    // One record: columns() × channels sums.
    void write(const std::vector<double>& record);
    void flush();
    // Closes the files and moves them into place. Without it (an error), they are removed.
    void finish();

private:
    struct Stream {
        std::string name;  // the file's, or empty for the standard output
        std::string partial;
        std::FILE* file = nullptr;
        std::vector<int> columns;
        std::string modifier;  // the modifier all its columns are of, empty if several (for MODIFIER=)
        int bin = 0;           // the bin of its first column (BIN= when it has one)
    };
    void writeHeader(Stream& s) const;

    OutputSettings settings_;
    std::vector<Stream> streams_;
    bool finished_ = false;
};

// The name an -o pattern gives modifier `name`'s bin `bin`; Error for other conversions.
std::string outputName(const std::string& pattern, const std::string& name, int bin);

}  // namespace brume
