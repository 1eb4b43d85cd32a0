#include "util/header.h"

#include <ctime>

namespace brume {

std::string commandLine(const std::vector<std::string>& words) {
    std::string line;
    for (const std::string& w : words) {
        if (!line.empty()) line += ' ';
        bool quote = w.empty() || w.find_first_of(" \t\n") != std::string::npos;
        char q = '"';
        for (size_t i = 1; i + 1 < w.size(); ++i)
            if (w[i] == '"' || w[i] == '\'') quote = true, q = w[i] == '"' ? '\'' : '"';
        line += quote ? q + w + q : w;
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

}  // namespace brume
