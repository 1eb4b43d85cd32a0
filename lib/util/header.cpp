#include "util/header.h"

#include <cctype>
#include <cstdlib>
#include <ctime>

namespace brume {

std::string quotedWord(const std::string& w) {
    bool quote = w.empty();
    char q = '"';
    for (size_t i = 0; i < w.size(); ++i) {
        if (std::isspace(static_cast<unsigned char>(w[i]))) quote = true;
        else if (i > 0 && i + 1 < w.size() && (w[i] == '"' || w[i] == '\'')) quote = true, q = w[i] == '"' ? '\'' : '"';
    }
    return quote ? q + w + q : w;
}

std::string commandLine(const std::vector<std::string>& words) {
    std::string line;
    for (const std::string& w : words) {
        if (!line.empty()) line += ' ';
        line += quotedWord(w);
    }
    return line;
}

std::string softwareAndDates() {
    std::time_t now = std::time(nullptr);
    char local[32], gmt[32];
    std::strftime(local, sizeof local, "%Y:%m:%d %H:%M:%S", std::localtime(&now));
    std::strftime(gmt, sizeof gmt, "%Y:%m:%d %H:%M:%S", std::gmtime(&now));
    return std::string("SOFTWARE= Brume ") + BRUME_VERSION + "\nCAPDATE= " + local + "\nGMT= " + gmt + "\n";
}

void endHeader(std::string& header, const std::string& format, std::FILE* out) {
    header += "FORMAT=" + format;
    int align = format == "float" ? 4 : format == "double" ? 8 : 0;
    long at = std::ftell(out);
    if (align && at >= 0) {
        int r = int((at + long(header.size()) + 2) % align);
        if (r) header += std::string(align - r, ' ');
    }
    header += "\n\n";
}

bool isHeaderVariable(std::string_view line, std::string_view name) { return line.substr(0, name.size()) == name; }

double headerProduct(const std::vector<std::string>& lines, std::string_view name) {
    double product = 1;
    for (const std::string& line : lines)
        if (isHeaderVariable(line, name)) product *= std::atof(line.c_str() + name.size());
    return product;
}

}  // namespace brume
