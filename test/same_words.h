// Comparing a program's text output with Radiance's word by word: the same words in the same order, numbers
// within a unit of their last printed digit (another libm may round the other way) and, where asked, within
// a relative tolerance (sums taken in another order).
#pragma once
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace brume_test {

inline std::vector<std::string> whitespaceWords(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> w;
    for (std::string s; in >> s;) w.push_back(s);
    return w;
}

// One unit of the last digit printed in `word` ("4.907e+06" → 1e3, "0.041013" → 1e-6), or 0 when the
// word is not a number.
inline double lastDigitUnit(const std::string& word) {
    char* end;
    std::strtod(word.c_str(), &end);
    if (end != word.c_str() + word.size() || word.find_first_of("0123456789") == std::string::npos) return 0;
    size_t e = word.find_first_of("eE"), dot = word.find('.');
    int decimals = dot == std::string::npos ? 0 : int((e == std::string::npos ? word.size() : e) - dot - 1);
    int exponent = e == std::string::npos ? 0 : std::stoi(word.substr(e + 1));
    return std::pow(10.0, exponent - decimals);
}

inline void expectSameWords(const std::string& brume, const std::string& radiance, const std::string& what,
                            double relative = 0) {
    std::vector<std::string> b = whitespaceWords(brume), r = whitespaceWords(radiance);
    ASSERT_EQ(b.size(), r.size()) << what << "\nBrume:\n" << brume.substr(0, 2000) << "Radiance:\n" << radiance.substr(0, 2000);
    int failures = 0;
    for (size_t i = 0; i < b.size() && failures < 10; ++i) {
        double unit = lastDigitUnit(r[i]);
        if (unit > 0 && lastDigitUnit(b[i]) > 0) {
            double x = std::stod(b[i]), y = std::stod(r[i]);
            bool close = std::abs(x - y) <= 1.01 * unit + relative * std::abs(y);
            EXPECT_TRUE(close) << what << ": word " << i << " " << b[i] << " vs " << r[i];
            failures += !close;
        } else {
            EXPECT_EQ(b[i], r[i]) << what << ": word " << i;
            failures += b[i] != r[i];
        }
    }
}

}  // namespace brume_test
