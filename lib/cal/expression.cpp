#include "cal/expression.h"

namespace brume::cal {

bool sameExpr(const Expr& a, const Expr& b) {
    if (a.kind != b.kind || a.number != b.number || a.channel != b.channel || a.name != b.name || a.ops != b.ops ||
        a.kids.size() != b.kids.size())
        return false;
    for (size_t i = 0; i < a.kids.size(); ++i)
        if (!sameExpr(a.kids[i], b.kids[i])) return false;
    return true;
}

}  // namespace brume::cal
