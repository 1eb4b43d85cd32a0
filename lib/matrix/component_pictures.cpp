#include "matrix/component_pictures.h"

#include <cctype>
#include <cstdio>

#include "io/picture.h"
#include "util/error.h"

namespace brume {

namespace {

// The conversions of a printf pattern: integer ones (%d, %03d, %i) and any other (but %%).
struct Conversions {
    int integers = 0, others = 0;
};

Conversions conversionsOf(const std::string& pattern) {
    Conversions c;
    for (size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '%') continue;
        size_t j = i + 1;
        while (j < pattern.size() && std::isdigit(static_cast<unsigned char>(pattern[j]))) ++j;
        if (j < pattern.size() && pattern[j] == '%' && j == i + 1) {
            i = j;
            continue;
        }
        bool integer = j < pattern.size() && (pattern[j] == 'd' || pattern[j] == 'i');
        (integer ? c.integers : c.others) += 1;
        i = j;
    }
    return c;
}

std::string nameOf(const std::string& pattern, int bin) {
    char name[4096];
    if (std::snprintf(name, sizeof name, pattern.c_str(), bin) >= int(sizeof name)) throw Error(pattern + ": name too long");
    return name;
}

}  // namespace

bool namesComponentPictures(const std::string& spec) { return conversionsOf(spec).integers > 0; }

Matrix sumComponentPictures(const std::string& pattern, const Matrix& weights, int step) {
    Conversions c = conversionsOf(pattern);
    if (c.integers != 1 || c.others != 0) throw Error(pattern + ": a picture pattern takes one %d (the bin) and %% only");
    Matrix sum;
    for (int b = 0; b < weights.rows; ++b) {
        const float* w = weights.at(b, step);
        bool zero = w[0] == 0 && w[weights.comps > 1 ? 1 : 0] == 0 && w[weights.comps > 2 ? 2 : 0] == 0;
        if (zero && b > 0) continue;
        std::string name = nameOf(pattern, b);
        Picture p = readPicture(name);
        if (b == 0) sum = Matrix(p.height, p.width, 3);
        else if (p.width != sum.cols || p.height != sum.rows)
            throw Error(name + ": " + std::to_string(p.width) + " by " + std::to_string(p.height) + ", not " +
                        std::to_string(sum.cols) + " by " + std::to_string(sum.rows) + " as the first picture");
        for (size_t i = 0; i < p.pixels.size(); ++i) sum.values[i] += p.pixels[i] * w[weights.comps == 3 ? i % 3 : 0];
    }
    return sum;
}

}  // namespace brume
