#include "visibility/sign_list.h"

#include "util/error.h"
#include "visibility/line_words.h"

namespace brume {

std::vector<SignEntry> readSignList(std::istream& in, const std::string& file) {
    std::vector<SignEntry> out;
    forEachWordLine(in, file, [&](const std::vector<std::string>& w, const std::string& where) {
        if (w.size() < 2 || w.size() > 3) throw Error(where + ": expected 'polygon emitting|reflecting [C]'");
        if (w[1] != "emitting" && w[1] != "reflecting")
            throw Error(where + ": sign '" + w[0] + "': kind '" + w[1] + "' is neither emitting nor reflecting");
        SignKind kind = w[1] == "emitting" ? SignKind::Emitting : SignKind::Reflecting;
        double c = jinConstant(kind);
        if (w.size() == 3 && !((c = realWord(w[2], where, "sign '" + w[0] + "': Jin's C")) > 0))
            throw Error(where + ": sign '" + w[0] + "': Jin's C must be > 0");
        for (const SignEntry& e : out)
            if (e.name == w[0]) throw Error(where + ": sign '" + w[0] + "' is listed twice (" + e.where + ")");
        out.push_back({w[0], kind, c, where});
    });
    if (out.empty()) throw Error(file + ": no signs");
    return out;
}

}  // namespace brume
