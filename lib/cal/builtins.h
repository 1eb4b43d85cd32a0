// The functions built into the .cal language: those of Radiance's calfunc.c (if, select, min, max, rand,
// floor, ceil, sqrt, trigonometry, exp, log, log10) and of rtrace (arg, erf, erfc, source_corr,
// source_theta, source_phi, noise3, noise3x/y/z, fnoise3). Everything else is defined in .cal files.
#pragma once
#include <span>
#include <string_view>

namespace brume::cal {

// What a built-in may read besides its arguments: the ray's channels and the pattern's real arguments.
struct RayInput {
    const double* channels = nullptr;
    std::span<const double> args;
};

struct Builtin {
    std::string_view name;
    // Arguments evaluated; a call with more ignores the rest (as Radiance does), one with fewer is an error.
    int arity;
    bool variadic;  // select, min, max: every argument counts
    bool readsRay;  // never folded into a constant
    // Returns NaN or an infinity for a domain or range error (the caller reports it); throws brume::Error
    // for a user error (a missing real argument).
    double (*fn)(const double* a, int n, const RayInput& ray);
};

// The built-in called `name`, or nullptr.
const Builtin* findBuiltin(std::string_view name);

// Radiance's arg(n): n rounded; 0 (or less) gives the count, beyond the count is an error.
double patternArgument(double n, std::span<const double> args);
// Radiance's select(n, a1, a2, ...): n rounded; 0 gives the count of choices, out of range is NaN.
// `choices` is the number of arguments after n.
int selectIndex(double n, int choices);

}  // namespace brume::cal
