#include "material/bsdf_klems.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace brume {

namespace {

Rgb entry(const KlemsMatrix& m, size_t k) {
    if (m.rgb.empty()) return {m.y[k], m.y[k], m.y[k]};
    return {m.rgb[3 * k], m.rgb[3 * k + 1], m.rgb[3 * k + 2]};
}

size_t entryIndex(const KlemsMatrix& m, int o, int i) { return size_t(o) * size_t(m.in->size()) + size_t(i); }

// The largest directional-hemispherical sum over the incident patches.
double maxHemispherical(const KlemsMatrix& m) {
    double best = 0;
    for (int i = 0; i < m.in->size(); ++i) {
        double sum = 0;
        for (int o = 0; o < m.out->size(); ++o) sum += m.value(o, i) * m.out->projectedSolidAngle(o);
        best = std::max(best, sum);
    }
    return best;
}

}  // namespace

// The view direction fixes the column of incident patch i (or, when the matrix has the view on its outgoing
// side, the row of outgoing patch o: reciprocity, as Radiance's library does); the entries along it are
// the light's patches.
struct KlemsBsdf::Slice {
    const KlemsMatrix* m;
    bool reverse;  // the view is the matrix's outgoing direction
    int fixed;
    double total;

    const KlemsBasis& basis() const { return reverse ? *m->in : *m->out; }
    const KlemsSide& side() const { return reverse ? m->inSide : m->outSide; }
    size_t index(int k) const { return reverse ? entryIndex(*m, fixed, k) : entryIndex(*m, k, fixed); }
    double weight(int k) const { return m->y[index(k)] * basis().projectedSolidAngle(k); }
    // The patch of the light direction along the slice, -1 if none; its value.
    int at(const dvec3& light) const { return side().index(basis(), light); }
    float y(int k) const { return m->y[index(k)]; }
};

KlemsBsdf::KlemsBsdf(KlemsData data)
    : reflectFront_(std::move(data.reflectFront)), reflectBack_(std::move(data.reflectBack)),
      transmitFront_(std::move(data.transmitFront)), transmitBack_(std::move(data.transmitBack)),
      ownBases_(std::move(data.ownBases)) {
    splitDiffuse(reflectFront_, reflectLamb_[0]);
    splitDiffuse(reflectBack_, reflectLamb_[1]);
    splitDiffuse(transmitFront_, transmitLamb_[0]);
    splitDiffuse(transmitBack_, transmitLamb_[1]);
    // One transmission matrix serves both sides (reciprocity), so does its Lambertian part.
    if (!transmitFront_ && transmitBack_) transmitLamb_[0] = transmitLamb_[1];
    if (transmitFront_ && !transmitBack_) transmitLamb_[1] = transmitLamb_[0];
    // Radiance drops distributions with nothing left beyond their Lambertian part.
    for (auto* m : {&reflectFront_, &reflectBack_, &transmitFront_, &transmitBack_}) {
        if (*m && maxHemispherical(**m) <= 0.001) m->reset();
        if (!*m) continue;
        const KlemsMatrix& x = **m;
        std::vector<double>& columns = columnTotals_[&x];
        std::vector<double>& rows = rowTotals_[&x];
        columns.assign(size_t(x.in->size()), 0.0);
        rows.assign(size_t(x.out->size()), 0.0);
        for (int o = 0; o < x.out->size(); ++o)
            for (int i = 0; i < x.in->size(); ++i) {
                columns[size_t(i)] += x.value(o, i) * x.out->projectedSolidAngle(o);
                rows[size_t(o)] += x.value(o, i) * x.in->projectedSolidAngle(i);
            }
    }
}

// Radiance's extract_diffuse: the matrix's smallest value, per channel, is Lambertian when its Y exceeds
// 0.01/π; it leaves the matrix.
void KlemsBsdf::splitDiffuse(std::optional<KlemsMatrix>& m, Rgb& lambertian) {
    if (!m) return;
    Rgb least{INFINITY, INFINITY, INFINITY};
    for (size_t k = 0; k < m->y.size(); ++k) {
        Rgb c = entry(*m, k);
        for (int j = 0; j < 3; ++j) least[size_t(j)] = std::min(least[size_t(j)], c[size_t(j)]);
    }
    double leastY = m->rgb.empty() ? least[0] : luminance(least);
    if (leastY <= 0.01 / M_PI) return;
    for (size_t k = 0; k < m->y.size(); ++k) {
        m->y[k] = std::max(0.f, m->y[k] - float(leastY));
        for (size_t j = 0; j < m->rgb.size() / m->y.size(); ++j) m->rgb[3 * k + j] -= least[j];
    }
    for (int j = 0; j < 3; ++j) lambertian[size_t(j)] = float(M_PI * least[size_t(j)]);
}

// Radiance's SDevalBSDF: reflection on the view's side, transmission through; with one transmission
// matrix, it serves both ways.
const KlemsMatrix* KlemsBsdf::matrix(bool viewFront, bool lightFront) const {
    if (viewFront && lightFront) return reflectFront_ ? &*reflectFront_ : nullptr;
    if (!viewFront && !lightFront) return reflectBack_ ? &*reflectBack_ : nullptr;
    const auto& mine = viewFront ? transmitFront_ : transmitBack_;
    const auto& other = viewFront ? transmitBack_ : transmitFront_;
    return mine ? &*mine : other ? &*other : nullptr;
}

std::optional<KlemsBsdf::Slice> KlemsBsdf::slice(const dvec3& view, bool transmit) const {
    bool front = view.z > 0;
    const KlemsMatrix* m = matrix(front, transmit ? !front : front);
    if (!m) return std::nullopt;
    if (int i = m->inSide.index(*m->in, view); i >= 0) return Slice{m, false, i, columnTotals_.at(m)[size_t(i)]};
    if (int o = m->outSide.index(*m->out, view); o >= 0) return Slice{m, true, o, rowTotals_.at(m)[size_t(o)]};
    return std::nullopt;
}

Rgb KlemsBsdf::value(const dvec3& view, const dvec3& light) const {
    auto s = slice(view, (view.z > 0) != (light.z > 0));
    if (!s) return {0, 0, 0};
    int k = s->at(light);
    return k < 0 ? Rgb{0, 0, 0} : entry(*s->m, s->index(k));
}

double KlemsBsdf::albedo(const dvec3& view, bool transmit) const {
    auto s = slice(view, transmit);
    return s ? s->total : 0.0;
}

// Radiance's SDsampComponent: a patch with probability ∝ its value × projected solid angle, then a
// direction uniform in projected solid angle inside it.
std::optional<dvec3> KlemsBsdf::sample(const dvec3& view, bool transmit, double u, double v) const {
    auto s = slice(view, transmit);
    if (!s) return std::nullopt;
    if (!(s->total > 1e-6)) return std::nullopt;
    double target = u * s->total;
    int last = s->basis().size() - 1, k = 0;
    for (; k < last && target >= s->weight(k); ++k) target -= s->weight(k);
    double w = s->weight(k);
    double within = w > 0 ? std::clamp(target / w, 0.0, 1.0 - 1e-12) : 0.5;
    return s->side().direction(s->basis(), k, within, v);
}

double KlemsBsdf::projectedPdf(const dvec3& view, const dvec3& light) const {
    auto s = slice(view, (view.z > 0) != (light.z > 0));
    if (!s) return 0;
    int k = s->at(light);
    return k < 0 || !(s->total > 1e-6) ? 0.0 : s->y(k) / s->total;
}

double KlemsBsdf::viewPatch(const dvec3& view, bool transmit) const {
    auto s = slice(view, transmit);
    if (!s) return 0;
    const KlemsBasis& b = s->reverse ? *s->m->out : *s->m->in;
    return b.projectedSolidAngle(s->fixed);
}

double KlemsBsdf::lightPatch(const dvec3& view, const dvec3& light) const {
    auto s = slice(view, (view.z > 0) != (light.z > 0));
    int k = s ? s->at(light) : -1;
    return k < 0 ? 0.0 : s->basis().projectedSolidAngle(k);
}

// bsdf_jitter: x and y moved by up to half the side each way, z kept, then normalized.
KlemsBsdf::Views KlemsBsdf::jittered(const dvec3& view, double side) {
    Views views;
    for (int a = 0; a < kJitter; ++a)
        for (int b = 0; b < kJitter; ++b) {
            double dx = ((a + 0.5) / kJitter - 0.5) * side, dy = ((b + 0.5) / kJitter - 0.5) * side;
            views[size_t(a * kJitter + b)] = glm::normalize(dvec3(view.x + dx, view.y + dy, view.z));
        }
    return views;
}

// Calls f(slice, light's patch along it) for each view with a slice toward the light's side. The light's
// patch is found once for all views that read the matrix the same way.
template <class F>
void KlemsBsdf::forEachView(const Views& views, const dvec3& light, F f) const {
    bool transmit = (views[0].z > 0) != (light.z > 0);
    std::optional<Slice> last;
    int k = -1;
    for (const dvec3& v : views) {
        auto s = slice(v, transmit);
        if (!s) continue;
        if (!last || last->m != s->m || last->reverse != s->reverse) k = s->at(light);
        last = s;
        f(*s, k);
    }
}

Rgb KlemsBsdf::smoothedValue(const dvec3& view, const dvec3& light) const {
    bool transmit = (view.z > 0) != (light.z > 0);
    double patch = std::min(viewPatch(view, transmit), lightPatch(view, light));
    Rgb sum{0, 0, 0};
    if (!(patch > 0)) return sum;
    forEachView(jittered(view, std::sqrt(patch)), light, [&](const Slice& s, int k) {
        if (k < 0) return;
        Rgb f = entry(*s.m, s.index(k));
        for (int c = 0; c < 3; ++c) sum[size_t(c)] += f[size_t(c)] / (kJitter * kJitter);
    });
    return sum;
}

double KlemsBsdf::smoothedAlbedo(const dvec3& view, bool transmit) const {
    double sum = 0;
    for (const dvec3& v : jittered(view, std::sqrt(viewPatch(view, transmit)))) sum += albedo(v, transmit);
    return sum / (kJitter * kJitter);
}

std::optional<dvec3> KlemsBsdf::smoothedSample(const dvec3& view, bool transmit, double u, double v) const {
    Views views = jittered(view, std::sqrt(viewPatch(view, transmit)));
    double total = 0;
    for (const dvec3& w : views) total += albedo(w, transmit);
    if (!(total > 1e-6)) return std::nullopt;
    double target = u * total;
    for (const dvec3& w : views) {
        double a = albedo(w, transmit);
        if (a > 0 && (target < a || &w == &views.back()))
            return sample(w, transmit, std::clamp(target / a, 0.0, 1 - 1e-12), v);
        target -= a;
    }
    return std::nullopt;
}

// The mixture of the jittered views' densities, each weighted by its albedo: Σ f / Σ albedo.
double KlemsBsdf::smoothedProjectedPdf(const dvec3& view, const dvec3& light) const {
    bool transmit = (view.z > 0) != (light.z > 0);
    double values = 0, total = 0;
    forEachView(jittered(view, std::sqrt(viewPatch(view, transmit))), light, [&](const Slice& s, int k) {
        total += s.total;
        if (k >= 0) values += s.y(k);
    });
    return total > 1e-6 ? values / total : 0.0;
}

}  // namespace brume
