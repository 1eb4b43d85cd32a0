// What rcontrib tallies: the modifiers it is given (-m, -M), and for each the bin a contribution falls in
// (an expression of the ray toward the source, -b, out of -bn bins) with the definitions of -e and -f and the
// modifier's own parameters (-p), as Radiance's rcontrib evaluates them.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "cal/program.h"
#include "contrib/reinhart_bins.h"
#include "world/render_scene.h"

namespace brume {

// A definition rcontrib loads for every modifier, in command-line order: an -e expression or an -f file.
struct CalDefinition {
    enum class Kind { Expression, File } kind;
    std::string text;  // the expression, or the file's name
};

// One -m, with the -b, -bn and -p in force where it was given.
struct ModifierRequest {
    std::string name;
    std::string bin = "0";       // -b: the bin of a contribution; a constant must be 0
    std::string binCount = "1";  // -bn: a count, or an expression of the definitions (Nrbins)
    std::string parameters;      // -p: "MF=1,rNx=0" (set after the definitions, for this modifier only)
    std::string output;          // -o: its file name pattern, empty: the standard output
};

class ModifierBins {
public:
    // Throws Error: a modifier the scene does not define or that is no light source (only those are told,
    // contributions.h), one given twice, a bin count below 1, a constant bin other than 0, definitions that
    // do not compile.
    ModifierBins(const Scene& scene, const RenderScene& render, const std::vector<CalDefinition>& definitions,
                 const std::vector<ModifierRequest>& requests);

    struct Tallied {
        std::string name;
        int bins;    // -bn
        int column;  // where its bins start among all modifiers'
        cal::Program program;
        cal::ExprId bin;
        bool constant;  // the bin is the number 0: one bin, nothing to evaluate
        std::optional<ReinhartBins> reinhart;  // Brume's reinhartb.cal's rbin, computed natively
        std::string output;                    // -o pattern, empty: the standard output
    };
    const std::vector<Tallied>& modifiers() const { return modifiers_; }
    // Every modifier's bins, one after another.
    int columns() const { return columns_; }
    // The tallied modifier a scene object (a contribution's modifier) stands for, or -1.
    int indexOf(int object) const { return object >= 0 && object < int(byObject_.size()) ? byObject_[object] : -1; }

private:
    std::vector<Tallied> modifiers_;
    std::vector<int> byObject_;
    int columns_ = 0;
};

}  // namespace brume
