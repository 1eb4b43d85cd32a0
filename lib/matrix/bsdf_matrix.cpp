#include "matrix/bsdf_matrix.h"

#include <algorithm>
#include <cctype>

#include "material/bsdf_xml.h"
#include "util/error.h"

namespace brume {

namespace {

// Entry (o, i) of a distribution in Radiance's RGB.
void entry(const KlemsMatrix& m, int o, int i, float* rgb) {
    size_t at = size_t(o) * size_t(m.in->size()) + size_t(i);
    for (int c = 0; c < 3; ++c) rgb[c] = m.rgb.empty() ? m.y[at] : m.rgb[3 * at + size_t(c)];
}

// The patch of `m`'s other direction that is the reverse of its patch p on this side (cmbsdf.c's
// recip_out_from_in and recip_in_from_out): a direction inside p, through the surface.
int reciprocal(const KlemsSide& from, const KlemsBasis& fromBasis, const KlemsSide& to, const KlemsBasis& toBasis, int p) {
    dvec3 d = from.direction(fromBasis, p, 0.5, 0.5);
    return to.index(toBasis, {d.x, d.y, -d.z});
}

}  // namespace

bool isBsdfFile(const std::string& spec) {
    if (spec.size() < 4) return false;
    std::string tail = spec.substr(spec.size() - 4);
    std::transform(tail.begin(), tail.end(), tail.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return tail == ".xml";
}

Matrix transmissionMatrix(const std::string& path) {
    KlemsData data = readKlemsXml(path, path);
    // Radiance's orientation: WINDOW's front transmission is transmitBack (bsdf_xml.h).
    if (const std::optional<KlemsMatrix>& t = data.transmitBack) {
        Matrix m(t->out->size(), t->in->size(), 3);
        for (int r = 0; r < m.rows; ++r)
            for (int c = 0; c < m.cols; ++c) {
                float* v = m.at(r, c);
                entry(*t, r, c, v);
                for (int k = 0; k < 3; ++k) v[k] = std::max(v[k], 0.f) * float(t->in->projectedSolidAngle(c));
            }
        return m;
    }
    const std::optional<KlemsMatrix>& t = data.transmitFront;
    if (!t) throw Error(path + ": no transmission to make a matrix of");
    Matrix m(t->in->size(), t->out->size(), 3);
    for (int c = 0; c < m.cols; ++c) {
        int o = reciprocal(t->inSide, *t->in, t->outSide, *t->out, c);
        for (int r = 0; r < m.rows; ++r) {
            int i = reciprocal(t->outSide, *t->out, t->inSide, *t->in, r);
            float* v = m.at(r, c);
            if (o < 0 || i < 0) continue;
            entry(*t, o, i, v);
            for (int k = 0; k < 3; ++k) v[k] = std::max(v[k], 0.f) * float(t->out->projectedSolidAngle(o));
        }
    }
    return m;
}

}  // namespace brume
