#include "visibility/line_words.h"

#include <cmath>
#include <sstream>

#include "util/error.h"

namespace brume {

std::vector<std::string> lineWords(const std::string& line) {
    std::istringstream in(line.substr(0, line.find('#')));
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

void forEachWordLine(std::istream& in, const std::string& file,
                     const std::function<void(const std::vector<std::string>&, const std::string&)>& use) {
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        std::vector<std::string> words = lineWords(line);
        if (!words.empty()) use(words, file + ":" + std::to_string(number));
    }
    if (in.bad()) throw Error(file + ": cannot be read");
}

double realWord(const std::string& word, const std::string& where, const std::string& what) {
    size_t used = 0;
    double v = 0;
    try {
        v = std::stod(word, &used);
    } catch (const std::exception&) {
        used = 0;
    }
    if (used != word.size() || !std::isfinite(v)) throw Error(where + ": " + what + " '" + word + "' is not a number");
    return v;
}

}  // namespace brume
