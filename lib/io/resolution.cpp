#include "io/resolution.h"

#include <sstream>

#include "util/error.h"

namespace brume {

std::pair<int, int> Resolution::pixel(int s, int k) const {
    int x = transposed ? s : k, y = transposed ? k : s;
    if (flipX) x = width - 1 - x;
    if (flipY) y = height - 1 - y;
    return {x, y};
}

long Resolution::storedIndex(int x, int y) const {
    if (flipX) x = width - 1 - x;
    if (flipY) y = height - 1 - y;
    return transposed ? long(x) * height + y : long(y) * width + x;
}

std::string Resolution::line() const {
    std::string x = std::string(flipX ? "-" : "+") + "X " + std::to_string(width);
    std::string y = std::string(flipY ? "+" : "-") + "Y " + std::to_string(height);
    return transposed ? x + " " + y : y + " " + x;
}

Resolution parseResolution(const std::string& line, const std::string& name) {
    std::istringstream s(line);
    std::string a, b;
    long na = 0, nb = 0;
    if (!(s >> a >> na >> b >> nb) || a.size() != 2 || b.size() != 2 || na <= 0 || nb <= 0 || na > 1 << 20 ||
        nb > 1 << 20 || a[1] == b[1] || (a[1] != 'X' && a[1] != 'Y') || (b[1] != 'X' && b[1] != 'Y') ||
        (a[0] != '+' && a[0] != '-') || (b[0] != '+' && b[0] != '-'))
        throw Error(name + ": bad resolution line \"" + line + "\"");
    Resolution r;
    r.transposed = a[1] == 'X';
    const std::string& x = r.transposed ? a : b;
    const std::string& y = r.transposed ? b : a;
    r.width = int(r.transposed ? na : nb);
    r.height = int(r.transposed ? nb : na);
    r.flipX = x[0] == '-';
    r.flipY = y[0] == '+';
    return r;
}

}  // namespace brume
