// The signs a visibility study asks about, one per line of a text file:
//   # polygon    kind         [Jin's C]
//   exit_sign    emitting
//   fire_plan    reflecting   3
// The kind is `emitting` (self-luminous: glows, back-lit panels) or `reflecting` (lit by the room's light);
// Jin's C defaults to 8 and 3 for them.
#pragma once
#include <istream>
#include <string>
#include <vector>

#include "visibility/sign.h"

namespace brume {

struct SignEntry {
    std::string name;
    SignKind kind;
    double jinConstant;
    std::string where;  // "file:line", for errors about the sign in the scene
};

// Throws Error "file:line: what is wrong" (an unknown kind, a bad or non-positive C, a name given twice, no signs).
std::vector<SignEntry> readSignList(std::istream& in, const std::string& file);

}  // namespace brume
