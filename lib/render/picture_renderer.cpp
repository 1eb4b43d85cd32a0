#include "render/picture_renderer.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include "render/progress.h"
#include "render/small_sources.h"
#include "view/aperture.h"
#include "view/pixel_aspect.h"

namespace brume {

namespace {

// The first-pass sample rows or columns: every `spacing`-th, and the last.
std::vector<int> gridLines(int n, int spacing) {
    std::vector<int> lines;
    for (int i = 0; i < n; i += spacing) lines.push_back(i);
    if (lines.back() != n - 1) lines.push_back(n - 1);
    return lines;
}

// Radiance's test for samples too different to interpolate between: any channel differing by more than
// `threshold` times the smaller value.
bool differ(const float* a, const float* b, double threshold) {
    for (int i = 0; i < 3; ++i)
        if (a[i] - b[i] > threshold * b[i] || b[i] - a[i] > threshold * a[i]) return true;
    return false;
}

class Renderer {
public:
    Renderer(const Integrator& integrator, const View& view, const PictureSettings& s, ProgressMeter* progress)
        : integrator_(integrator), view_(view), s_(s), progress_(progress), w_(s.xres), h_(s.yres) {
        out_.picture.width = w_, out_.picture.height = h_;
        out_.picture.pixelAspect = s.pixelAspect;
        out_.picture.pixels.assign(size_t(w_) * h_ * 3, 0.f);
        depth_.assign(size_t(w_) * h_, 0.f);
        traced_.assign(size_t(w_) * h_, 0);
    }

    RenderedPicture run() {
        bool adapt = s_.sampleSpacing > 1 && w_ >= 2 && h_ >= 2;
        if (adapt) xs_ = gridLines(w_, s_.sampleSpacing), ys_ = gridLines(h_, s_.sampleSpacing);
        // Progress counts pixels as they are settled: traced or interpolated.
        if (progress_) progress_->start(long(w_) * h_);
        if (adapt) adaptive();
        else traceAll();
        if (s_.drawSources && !s_.irradiance)
            drawSmallSources(integrator_, integrator_.scene(), view_, std::max(1, s_.sampleSpacing), out_.picture,
                             s_.depth ? &depth_ : nullptr);
        if (progress_) progress_->finish();
        if (s_.depth) out_.depth = std::move(depth_);
        return std::move(out_);
    }

private:
    size_t at(int x, int row) const { return size_t(row) * w_ + x; }
    float* pixel(int x, int row) { return out_.picture.at(x, row); }

    // One ray through pixel (x, row): its value and distance stored, the pixel marked traced.
    void trace(int x, int row) {
        size_t i = at(x, row);
        uint64_t index = i;
        Random random(integrator_.seedFor(index) ^ 0x6a09e667f3bcc909ULL, index);  // this pixel's jitter and lens
        double jx = 0.5 + s_.jitter * (0.5 - random.uniform()), jy = 0.5 + s_.jitter * (0.5 - random.uniform());
        // The view's y runs up from the bottom edge; rows run down from the top.
        std::optional<ViewRay> ray = view_.ray((x + jx) / w_, (h_ - 1 - row + jy) / h_);
        traced_[i] = 1;
        if (ray && s_.aperture > 0 &&
            !jitterAperture(view_, *ray, s_.aperture, random.uniform(), random.uniform(), random.uniform()))
            ray.reset();
        if (!ray) return;  // outside a fisheye's circle, or no lens ray: black, as Radiance
        RayRecord rec = s_.irradiance
                            ? integrator_.irradianceAtHit(ray->org, ray->dir, index)
                            : integrator_.trace(ray->org, ray->dir, index, std::isfinite(ray->tmax) ? ray->tmax : 0);
        for (int c = 0; c < 3; ++c) pixel(x, row)[c] = rec.value[c];
        // Radiance's ray distance: the mirror image's when the mirrored light dominates, else the effective one.
        bool mirrored = brightness(rec.mirrored) > 0.5f * brightness(rec.value);
        double d = mirrored ? rec.mirroredLength : rec.effectiveLength;
        depth_[i] = std::isfinite(d) ? float(d) : 0.f;
    }

    void traceAll() {
        tbb::parallel_for(0, h_, [&](int row) {
            for (int x = 0; x < w_; ++x) trace(x, row);
            if (progress_) progress_->advance(w_, w_);
        });
    }

    // The first pass samples the grid; then the pixels between grid samples along the grid lines, then those
    // inside each tile, are refined: where the ends (corners) agree they are interpolated, else the middle is
    // traced and each half refined in turn (Radiance's recursive refinement). Each pixel belongs to one grid
    // segment or one tile, and each is refined by one task in a fixed order, so the picture does not depend
    // on the threads.
    void adaptive() {
        const std::vector<int>&xs = xs_, &ys = ys_;
        tbb::parallel_for(size_t(0), ys.size(), [&](size_t j) {
            for (int x : xs) trace(x, ys[j]);
            if (progress_) progress_->advance(long(xs.size()), long(xs.size()));
        });
        size_t nx = xs.size() - 1, ny = ys.size() - 1;
        // Segments: the horizontal ones (ny + 1 rows of nx), then the vertical ones (nx + 1 columns of ny).
        tbb::parallel_for(size_t(0), (ny + 1) * nx + (nx + 1) * ny, [&](size_t k) {
            bool across = k < (ny + 1) * nx;
            size_t i = across ? k % nx : (k - (ny + 1) * nx) / ny, j = across ? k / nx : (k - (ny + 1) * nx) % ny;
            Span a{xs[i], ys[j]}, b = across ? Span{xs[i + 1], ys[j]} : Span{xs[i], ys[j + 1]};
            long traced = refineSegment(a, b);
            if (progress_) progress_->advance(std::max(b.x - a.x, b.row - a.row) - 1, traced);
        });
        tbb::parallel_for(size_t(0), nx * ny, [&](size_t k) {
            size_t i = k % nx, j = k / nx;
            long traced = refineTile(xs[i], ys[j], xs[i + 1], ys[j + 1]);
            if (progress_) progress_->advance(long(xs[i + 1] - xs[i] - 1) * (ys[j + 1] - ys[j] - 1), traced);
        });
    }

    struct Span {
        int x, row;
    };

    bool agree(const Span& a, const Span& b) { return !differ(pixel(a.x, a.row), pixel(b.x, b.row), s_.sampleThreshold); }

    // Pixels strictly between a and b (on one row or column), a and b settled; returns how many were traced.
    long refineSegment(Span a, Span b) {
        int n = std::max(b.x - a.x, b.row - a.row);
        if (n <= 1) return 0;
        if (agree(a, b)) {
            for (int k = 1; k < n; ++k) {
                Span p{a.x + (b.x - a.x) * k / n, a.row + (b.row - a.row) * k / n};
                blend(p, {at(a.x, a.row), at(b.x, b.row)}, {double(n - k) / n, double(k) / n});
            }
            return 0;
        }
        Span m{(a.x + b.x) / 2, (a.row + b.row) / 2};
        trace(m.x, m.row);
        return 1 + refineSegment(a, m) + refineSegment(m, b);
    }

    // Pixels strictly inside the tile (x0, y0)-(x1, y1), its edges settled: interpolated if its corners agree
    // and none of its edge pixels needed tracing, else split across its longer side, the split line refined
    // first. Returns how many were traced.
    long refineTile(int x0, int y0, int x1, int y1) {
        if (x1 - x0 <= 1 || y1 - y0 <= 1) return 0;
        Span c[4] = {{x0, y0}, {x1, y0}, {x0, y1}, {x1, y1}};
        bool busy = !agree(c[0], c[1]) || !agree(c[0], c[2]) || !agree(c[0], c[3]) || !agree(c[1], c[2]) ||
                    !agree(c[1], c[3]) || !agree(c[2], c[3]);
        for (int x = x0 + 1; x < x1 && !busy; ++x) busy = traced_[at(x, y0)] || traced_[at(x, y1)];
        for (int y = y0 + 1; y < y1 && !busy; ++y) busy = traced_[at(x0, y)] || traced_[at(x1, y)];
        if (!busy) {
            for (int y = y0 + 1; y < y1; ++y)
                for (int x = x0 + 1; x < x1; ++x) {
                    double u = double(x - x0) / (x1 - x0), v = double(y - y0) / (y1 - y0);
                    blend({x, y}, {at(x0, y0), at(x1, y0), at(x0, y1), at(x1, y1)},
                          {(1 - u) * (1 - v), u * (1 - v), (1 - u) * v, u * v});
                }
            return 0;
        }
        if (x1 - x0 >= y1 - y0) {
            int xm = (x0 + x1) / 2;
            return refineSegment({xm, y0}, {xm, y1}) + refineTile(x0, y0, xm, y1) + refineTile(xm, y0, x1, y1);
        }
        int ym = (y0 + y1) / 2;
        return refineSegment({x0, ym}, {x1, ym}) + refineTile(x0, y0, x1, ym) + refineTile(x0, ym, x1, y1);
    }

    // Pixel p as the weighted sum of settled pixels (their indices), depth too.
    void blend(Span p, std::initializer_list<size_t> from, std::initializer_list<double> weights) {
        float* out = pixel(p.x, p.row);
        float d = 0;
        auto w = weights.begin();
        for (size_t i : from) {
            const float* c = &out_.picture.pixels[3 * i];
            for (int ch = 0; ch < 3; ++ch) out[ch] += float(*w) * c[ch];
            d += float(*w++) * depth_[i];
        }
        depth_[at(p.x, p.row)] = d;
    }

    const Integrator& integrator_;
    const View& view_;
    const PictureSettings& s_;
    ProgressMeter* progress_;
    int w_, h_;
    RenderedPicture out_;
    std::vector<float> depth_;
    std::vector<char> traced_;
    std::vector<int> xs_, ys_;  // the first pass's columns and rows
};

}  // namespace

void fitResolution(const View& view, PictureSettings& s) {
    normalizeResolution(view.aspect(), s.pixelAspect, s.xres, s.yres);
}

RenderedPicture renderPicture(const Integrator& integrator, const View& view, const PictureSettings& settings,
                              ProgressMeter* progress) {
    return Renderer(integrator, view, settings, progress).run();
}

}  // namespace brume
