// The study's small text inputs (sign lists, waypoints): a line's words before any '#', and numbers among them.
#pragma once
#include <functional>
#include <istream>
#include <string>
#include <vector>

namespace brume {

std::vector<std::string> lineWords(const std::string& line);
// Calls use(words, "file:line") for each line of `in` with words. Error "file: cannot be read" when reading fails.
void forEachWordLine(std::istream& in, const std::string& file,
                     const std::function<void(const std::vector<std::string>&, const std::string&)>& use);
// The finite number `word`; Error "where: what 'word' is not a number" otherwise.
double realWord(const std::string& word, const std::string& where, const std::string& what);

}  // namespace brume
