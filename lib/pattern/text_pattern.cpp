#include "pattern/text_pattern.h"

#include <algorithm>
#include <cmath>
#include <fstream>

#include "pattern/text_layout.h"
#include "scene/raypath.h"
#include "spectrum/rgb_to_spectrum.h"
#include "util/error.h"

namespace brume {

namespace {

// Where each type's arguments are: the font file's and the text's string, and the optional spacing
// after the real arguments every object of the type has.
struct Layout {
    size_t font, text, spacing;
};

Layout argumentLayout(const std::string& type) {
    if (type == "mixtext") return {2, 3, 9};
    return {0, 1, type == "colortext" ? 15u : 11u};
}

[[noreturn]] void badArguments(const SceneObject& o, const std::string& why) {
    throw Error(o.where, "bad arguments for " + o.type + " \"" + o.name + "\": " + why);
}

// A text file's lines, newlines removed.
std::vector<std::string> readLines(const SceneObject& o, const std::string& name) {
    std::string path = findOnRayPath(name);
    if (path.empty()) throw Error(o.where, "cannot find text file \"" + name + "\"");
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(o.where, "cannot open text file \"" + path + "\"");
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// The text: the string arguments after the text's own, joined by spaces, if there are any (that one is then
// a placeholder, "." by convention); otherwise the lines of the file it names.
std::vector<std::string> textOf(const SceneObject& o, size_t index) {
    if (o.strings.size() == index + 1) return readLines(o, o.strings[index]);
    std::string line;
    for (size_t i = index + 1; i < o.strings.size(); ++i) line += (i > index + 1 ? " " : "") + o.strings[i];
    return {line};
}

// The text block's place: a point's offset from the upper left corner measured along the right and down
// vectors (each along its own, parallel to the other: the dual basis, so that a slanted down vector slants
// the writing), in font units across and in lines down.
class TextFrame {
public:
    TextFrame(const SceneObject& o, double unitsAcross) : unitsAcross_(unitsAcross) {
        dvec3 r(o.reals[3], o.reals[4], o.reals[5]), d(o.reals[6], o.reals[7], o.reals[8]);
        origin_ = dvec3(o.reals[0], o.reals[1], o.reals[2]);
        dvec3 normal = glm::cross(d, r);
        right_ = glm::cross(normal, d);
        down_ = glm::cross(r, normal);
        double rr = glm::dot(right_, right_);  // |d|² |d × r|², the down vector's as big with r
        if (!(rr > 1e-24)) throw Error(o.where, o.type + " \"" + o.name + "\": illegal motion vector");
        right_ *= glm::dot(d, d) / rr;
        down_ *= glm::dot(r, r) / glm::dot(down_, down_);
    }
    // The hit point in the text's terms (in the frame of its instance or mesh, if any).
    void locate(const PatternHit& hit, double& across, double& down) const {
        dvec3 p = hit.object ? hit.object->toObject.point(hit.point) : hit.point;
        across = glm::dot(p - origin_, right_) * unitsAcross_;
        down = glm::dot(p - origin_, down_);
    }

private:
    dvec3 origin_, right_, down_;
    double unitsAcross_;  // font units to a right vector
};

// What the three types share: the text set in its font, and where it lies.
class PlacedText {
public:
    PlacedText(const SceneObject& o, PatternLibrary& lib)
        : PlacedText(o, checkedFont(o, lib, argumentLayout(o.type)), argumentLayout(o.type)) {}
    bool covers(const PatternHit& hit) const {
        double across, down;
        frame_.locate(hit, across, down);
        return layout_.covers(across, down);
    }

private:
    // With a spacing argument, the right vector spans a mean glyph and the spacing; without, a whole cell.
    PlacedText(const SceneObject& o, const Font& font, Layout a)
        : layout_(textOf(o, a.text), font, spacingUnits(spacing(o, a))),
          frame_(o, o.reals.size() > a.spacing ? font.meanWidth() + 255.0 * std::abs(spacing(o, a)) : 255.0) {}

    static const Font& checkedFont(const SceneObject& o, PatternLibrary& lib, Layout a) {
        if (o.strings.size() < a.text + 1) badArguments(o, "too few string arguments");
        if (!o.integers.empty()) badArguments(o, "no integer arguments expected");
        if (o.reals.size() < a.spacing) badArguments(o, "too few real arguments");
        return lib.font(o.strings[a.font], o.where);
    }
    static double spacing(const SceneObject& o, Layout a) { return o.reals.size() > a.spacing ? o.reals[a.spacing] : 0; }
    // In font units, truncated as Radiance's; bounded so that no line's length overflows.
    static int spacingUnits(double spacing) {
        double units = spacing * 255.0;
        return std::isfinite(units) ? int(std::clamp(units, -1e5, 1e5)) : 0;
    }

    TextLayout layout_;
    TextFrame frame_;
};

class TextPattern : public Pattern {
public:
    TextPattern(const SceneObject& o, PatternLibrary& lib) : text_(o, lib) {
        const std::vector<double>& v = o.reals;
        if (o.type == "brighttext") foreground_ = Spectrum(float(v[9])), background_ = Spectrum(float(v[10]));
        else foreground_ = spectrumFromRgb(v[9], v[10], v[11]), background_ = spectrumFromRgb(v[12], v[13], v[14]);
    }
    void apply(const PatternHit& hit, PatternEvaluator&, Texturing& t) const override {
        t.color *= text_.covers(hit) ? foreground_ : background_;
    }

private:
    PlacedText text_;
    Spectrum foreground_, background_;
};

class TextMixture : public Mixture {
public:
    TextMixture(const SceneObject& o, PatternLibrary& lib) : text_(o, lib) {}
    double coefficient(const PatternHit& hit, PatternEvaluator&) const override { return text_.covers(hit) ? 1 : 0; }

private:
    PlacedText text_;
};

}  // namespace

std::unique_ptr<Pattern> makeTextPattern(const SceneObject& o, PatternLibrary& library) {
    return std::make_unique<TextPattern>(o, library);
}

std::unique_ptr<Mixture> makeTextMixture(const SceneObject& o, PatternLibrary& library) {
    return std::make_unique<TextMixture>(o, library);
}

}  // namespace brume
