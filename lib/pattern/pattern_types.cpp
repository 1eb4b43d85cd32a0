// Radiance's patterns, textures and mixtures (reference manual §"Textures", "Patterns", "Mixtures"; the
// argument layouts and evaluation order follow its rt/p_func.c, p_data.c, t_func.c, t_data.c, mx_func.c
// and mx_data.c).
#include "pattern/pattern_types.h"

#include <algorithm>

#include "pattern/function_object.h"
#include "pattern/spectral_pattern.h"
#include "pattern/text_pattern.h"
#include "spectrum/rgb_to_spectrum.h"
#include "util/error.h"

namespace brume {

namespace {

// brightfunc (one value) and colorfunc (three).
class FunctionColor : public Pattern {
public:
    FunctionColor(const SceneObject& o, PatternLibrary& lib, int channels)
        : f_(functionObject(o, lib, size_t(channels), 0, size_t(channels))) {}
    void apply(const PatternHit& hit, PatternEvaluator& e, Texturing& t) const override {
        cal::Evaluator& eval = f_.begin(hit, e);
        if (f_.exprs.size() == 1) t.color *= float(eval(f_.exprs[0]));
        else t.color *= spectrumFromRgb(eval(f_.exprs[0]), eval(f_.exprs[1]), eval(f_.exprs[2]));
    }

private:
    FunctionObject f_;
};

// texfunc: a perturbation vector in pattern coordinates.
class FunctionTexture : public Pattern {
public:
    FunctionTexture(const SceneObject& o, PatternLibrary& lib) : f_(functionObject(o, lib, 3, 0, 3)) {}
    void apply(const PatternHit& hit, PatternEvaluator& e, Texturing& t) const override {
        cal::Evaluator& eval = f_.begin(hit, e);
        dvec3 d(eval(f_.exprs[0]), eval(f_.exprs[1]), eval(f_.exprs[2]));
        t.perturbation += f_.frame.toWorldVector(d, hit);
    }

private:
    FunctionObject f_;
};

// A function of some of the interpolated values (which, and how many, by Radiance's rules per type).
struct ValueFunction {
    cal::FuncId id;
    int first = 0, count = 1;
};

// The data a *data or *pict modifier interpolates and the functions that turn it into values.
struct Table {
    std::vector<const DataGrid*> grids;  // one per value, or one picture of three channels
    std::vector<ValueFunction> functions;
};

// Interpolates the grids at the coordinates the object's expressions give (pictures: u, v in that order,
// looked up as v, u); its functions then turn the interpolated values into the pattern's values.
class DataLookup {
public:
    DataLookup(FunctionObject f, Table t, bool picture) : f_(std::move(f)), t_(std::move(t)), picture_(picture) {}

    // Fills values[0…2]; returns how many there are.
    int interpolate(const PatternHit& hit, PatternEvaluator& e, double* values) const {
        cal::Evaluator& eval = f_.begin(hit, e);
        double point[DataGrid::kMaxDimensions];
        size_t n = f_.exprs.size();
        for (size_t i = 0; i < n; ++i) point[i] = eval(f_.exprs[i]);
        if (picture_) std::swap(point[0], point[1]);
        float v[3];
        int count = 0;
        for (const DataGrid* g : t_.grids) {
            g->interpolate(std::span<const double>(point, n), v);
            for (int c = 0; c < g->channels(); ++c) values[count++] = v[c];
        }
        return count;
    }
    double call(PatternEvaluator& e, int k, const double* values) const {
        const ValueFunction& f = t_.functions[size_t(k)];
        return e.eval(f.id, std::span<const double>(values + f.first, size_t(f.count)));
    }
    const FunctionObject& object() const { return f_; }

private:
    FunctionObject f_;
    Table t_;
    bool picture_;
};

// brightdata, colordata, colorpict (colours) and texdata (perturbations).
class DataPattern : public Pattern {
public:
    DataPattern(DataLookup lookup, bool texture) : lookup_(std::move(lookup)), texture_(texture) {}
    void apply(const PatternHit& hit, PatternEvaluator& e, Texturing& t) const override {
        double v[3];
        int count = lookup_.interpolate(hit, e, v);
        if (texture_) {
            dvec3 d(lookup_.call(e, 0, v), lookup_.call(e, 1, v), lookup_.call(e, 2, v));
            t.perturbation += lookup_.object().frame.toWorldVector(d, hit);
        } else {
            t.color *= count == 1 ? Spectrum(float(lookup_.call(e, 0, v)))
                                  : spectrumFromRgb(lookup_.call(e, 0, v), lookup_.call(e, 1, v), lookup_.call(e, 2, v));
        }
    }

private:
    DataLookup lookup_;
    bool texture_;
};

// Radiance's rules for which values each function gets (p_data.c, t_data.c, mx_data.c): with one value,
// that value; a texture's functions and the first colour function all three; the other colour functions
// their own value alone if they take fewer than three parameters.
void addFunctions(const SceneObject& o, PatternLibrary& lib, const FunctionObject& f, size_t count, int values,
                  bool texture, Table& t) {
    for (size_t k = 0; k < count; ++k) {
        const std::string& name = o.strings[k];
        ValueFunction v{{}, 0, values};
        if (values == 3 && !texture && k > 0 && lib.parameters(name, f.scope) < 3) v = ValueFunction{{}, int(k), 1};
        v.id = lib.function(name, v.count, f.scope, o.where);
        t.functions.push_back(v);
    }
}

// The lookup of a *data type: `functions` functions at strings[0…), then `files` data files, the function
// file, and one coordinate expression per data dimension.
DataLookup dataLookup(const SceneObject& o, PatternLibrary& lib, size_t functions, size_t files, bool texture = false) {
    if (o.strings.size() < functions + files + 1) badArguments(o, "too few string arguments");
    Table t;
    for (size_t i = 0; i < files; ++i) t.grids.push_back(&lib.dataFile(o.strings[functions + i]));
    size_t dims = size_t(t.grids[0]->dimensions());
    for (const DataGrid* g : t.grids)
        if (size_t(g->dimensions()) != dims) throw Error(o.where, o.type + " \"" + o.name + "\": dimension error");
    size_t file = functions + files;
    FunctionObject f = functionObject(o, lib, file, file + 1, dims);
    addFunctions(o, lib, f, functions, int(files), texture, t);
    return DataLookup(std::move(f), std::move(t), false);
}

// colorpict and mixpict: `functions` functions of the pixel's three values, the picture, the function
// file, then the u and v expressions.
DataLookup pictureLookup(const SceneObject& o, PatternLibrary& lib, size_t functions) {
    if (o.strings.size() < functions + 4) badArguments(o, "too few string arguments");
    Table t;
    t.grids.push_back(&lib.picture(o.strings[functions]));
    FunctionObject f = functionObject(o, lib, functions + 1, functions + 2, 2);
    addFunctions(o, lib, f, functions, 3, false, t);
    return DataLookup(std::move(f), std::move(t), true);
}

int modifierArgument(const Scene& scene, int object, const std::string& name) {
    if (name == "void") return -1;
    int m = scene.modifierBefore(object, name);
    const SceneObject& o = scene.objects[object];
    if (m < 0) throw Error(o.where, "undefined modifier \"" + name + "\" in " + o.type + " \"" + o.name + "\"");
    return m;
}

class FunctionMixture : public Mixture {
public:
    FunctionMixture(const SceneObject& o, PatternLibrary& lib) : f_(functionObject(o, lib, 3, 2, 1)) {}
    double coefficient(const PatternHit& hit, PatternEvaluator& e) const override {
        return f_.begin(hit, e)(f_.exprs[0]);
    }

private:
    FunctionObject f_;
};

class DataMixture : public Mixture {
public:
    explicit DataMixture(DataLookup lookup) : lookup_(std::move(lookup)) {}
    double coefficient(const PatternHit& hit, PatternEvaluator& e) const override {
        double v[3];
        lookup_.interpolate(hit, e, v);
        return lookup_.call(e, 0, v);
    }

private:
    DataLookup lookup_;
};

// Mixtures name their foreground and background first; the rest is laid out as for patterns.
SceneObject withoutModifierNames(const SceneObject& o) {
    SceneObject rest = o;
    rest.strings.erase(rest.strings.begin(), rest.strings.begin() + std::min<size_t>(2, rest.strings.size()));
    return rest;
}

}  // namespace

std::unique_ptr<Pattern> makePattern(const Scene& scene, int object, PatternLibrary& lib) {
    const SceneObject& o = scene.objects[object];
    if (o.type == "brightfunc") return std::make_unique<FunctionColor>(o, lib, 1);
    if (o.type == "colorfunc") return std::make_unique<FunctionColor>(o, lib, 3);
    if (o.type == "texfunc") return std::make_unique<FunctionTexture>(o, lib);
    if (o.type == "brightdata") return std::make_unique<DataPattern>(dataLookup(o, lib, 1, 1), false);
    if (o.type == "colordata") return std::make_unique<DataPattern>(dataLookup(o, lib, 3, 3), false);
    if (o.type == "texdata") return std::make_unique<DataPattern>(dataLookup(o, lib, 3, 3, true), true);
    if (o.type == "colorpict") return std::make_unique<DataPattern>(pictureLookup(o, lib, 3), false);
    if (o.type == "brighttext" || o.type == "colortext") return makeTextPattern(o, lib);
    if (isSpectralPatternType(o.type)) return makeSpectralPattern(o, lib);
    throw Error(o.where, "type '" + o.type + "' (" + o.name + ") is not supported by Brume yet");
}

std::unique_ptr<Mixture> makeMixture(const Scene& scene, int object, PatternLibrary& lib) {
    const SceneObject& o = scene.objects[object];
    if (o.strings.size() < 2) badArguments(o, "too few string arguments");
    std::unique_ptr<Mixture> mix;
    if (o.type == "mixfunc") mix = std::make_unique<FunctionMixture>(o, lib);
    else if (o.type == "mixdata") mix = std::make_unique<DataMixture>(dataLookup(withoutModifierNames(o), lib, 1, 1));
    else if (o.type == "mixpict") mix = std::make_unique<DataMixture>(pictureLookup(withoutModifierNames(o), lib, 1));
    else if (o.type == "mixtext") mix = makeTextMixture(o, lib);
    else throw Error(o.where, "type '" + o.type + "' (" + o.name + ") is not supported by Brume yet");
    mix->foreground = modifierArgument(scene, object, o.strings[0]);
    mix->background = modifierArgument(scene, object, o.strings[1]);
    return mix;
}

}  // namespace brume
