// An FDS input file (.fds) as namelist groups: "&OBST ID='wall' XB=9.9,10,0,10,0,3 /", each starting where '&'
// is the first word of a line. Text outside groups is comment, as FDS takes it. Each group keeps its parameters' values as written: strings unquoted, numbers and
// logicals as their text. Only what building the case's geometry needs is interpreted (case_geometry.h).
#pragma once
#include <istream>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace brume {

struct FdsGroup {
    std::string name;  // "OBST", "MESH", … (upper case)
    std::string where;  // "file:line" of its '&'
    std::map<std::string, std::vector<std::string>> values;  // parameter (upper case, as "SURF_IDS") → its values

    // The parameter's values, or none.
    const std::vector<std::string>* find(const std::string& key) const;
    // Its one string (e.g. ID, SURF_ID), or none.
    std::optional<std::string> text(const std::string& key) const;
    // Its n numbers; Error "where: NAME KEY: …" where there are not n, or one is not a number. None if absent.
    std::optional<std::vector<double>> numbers(const std::string& key, size_t n) const;
};

// `s` in upper case, as FDS compares names and colours.
std::string upperCase(std::string s);

// The groups of `in` in order. Throws Error "file:line: what" where a group is not closed by '/', a string by its
// quote, or a parameter has no '=' or no value.
std::vector<FdsGroup> readFdsInput(std::istream& in, const std::string& file);

}  // namespace brume
