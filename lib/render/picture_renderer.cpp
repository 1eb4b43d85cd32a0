#include "render/picture_renderer.h"

#include <algorithm>
#include <cmath>

#include "render/progress.h"
#include "render/sequence.h"
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

// Radiance's test for samples too different to interpolate between: any of R, G, B differing by more than
// `threshold` times the smaller value.
bool differ(const float* a, const float* b, double threshold) {
    for (int i = 0; i < 3; ++i)
        if (a[i] - b[i] > threshold * b[i] || b[i] - a[i] > threshold * a[i]) return true;
    return false;
}

class Renderer {
public:
    Renderer(Sequence& sequence, const View& view, double time, const PictureSettings& s, ProgressMeter* progress)
        : sequence_(sequence), integrator_(sequence.integrator()), view_(view), time_(time), s_(s), progress_(progress),
          w_(s.xres), h_(s.yres) {
        values_.width = w_, values_.height = h_, values_.channels = c_;
        values_.values.assign(size_t(w_) * h_ * c_, 0.f);
        if (c_ > 3) colours_.assign(size_t(w_) * h_ * 3, 0.f);
        depth_.assign(size_t(w_) * h_, 0.f);
        traced_.assign(size_t(w_) * h_, 0);
    }

    RenderedPicture run() {
        bool adapt = s_.sampleSpacing > 1 && w_ >= 2 && h_ >= 2;
        if (adapt) xs_ = gridLines(w_, s_.sampleSpacing), ys_ = gridLines(h_, s_.sampleSpacing);
        // Progress counts the first pass's samples, then every pixel again as its row is settled.
        if (progress_) progress_->start(long(w_) * h_ + long(xs_.size() * ys_.size()));
        if (adapt) adaptive();
        else traceAll();
        if (s_.drawSources && !s_.irradiance)
            drawSmallSources(integrator_, time_, view_, std::max(1, s_.sampleSpacing), values_, s_.depth ? &depth_ : nullptr);
        if (progress_) progress_->finish();
        RenderedPicture out;
        out.picture = picture();
        if (s_.depth) out.depth = std::move(depth_);
        if (c_ > 3) out.spectra = std::move(values_);
        return out;
    }

private:
    size_t at(int x, int row) const { return size_t(row) * w_ + x; }
    float* pixel(int x, int row) { return values_.at(x, row); }
    // A traced pixel's RGB: what the first pass compares (bands would differ more often than the colour
    // seen, the more of them there are). In RGB, the pixel itself.
    float* colour(int x, int row) { return c_ > 3 ? &colours_[3 * at(x, row)] : pixel(x, row); }

    // The three channels -pRGB, -pXYZ or -pc ask for (Radiance's rpict writes XYZ × 179, as rtrace does).
    Picture picture() const {
        Picture p;
        p.width = w_, p.height = h_, p.pixelAspect = s_.pixelAspect;
        p.xyz = s_.color.kind == ColorOutput::Kind::Xyz;
        p.pixels.resize(size_t(w_) * h_ * 3);
        Spectrum v(0.f, c_);
        double rgb[3];
        for (size_t i = 0; i < size_t(w_) * h_; ++i) {
            std::copy_n(&values_.values[i * c_], c_, &v[0]);
            s_.color.convert(v, rgb);
            for (int k = 0; k < 3; ++k) p.pixels[3 * i + k] = float(rgb[k]);
        }
        return p;
    }

    // One ray through pixel (x, row): its value and distance stored, the pixel marked traced.
    void trace(int x, int row, WorkItem& item) {
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
        RayQuery q{ray->org, ray->dir, index, time_, std::isfinite(ray->tmax) ? ray->tmax : 0};
        RayRecord rec = s_.irradiance ? integrator_.irradianceAtHit(q, item) : integrator_.trace(q, item);
        for (int c = 0; c < c_; ++c) pixel(x, row)[c] = rec.value[c];
        if (c_ > 3) {
            Color3 rgb = toRgb(rec.value);
            std::copy(rgb.begin(), rgb.end(), colour(x, row));
        }
        // Radiance's ray distance: the mirror image's when the mirrored light dominates, else the effective one.
        bool mirrored = brightness(rec.mirrored) > 0.5f * brightness(rec.value);
        double d = mirrored ? rec.mirroredLength : rec.effectiveLength;
        depth_[i] = std::isfinite(d) ? float(d) : 0.f;
    }

    // Traces the pixels listed, by the sequence's passes (its cache's records are made between them).
    void traceEach(const std::vector<std::pair<int, int>>& pixels) {
        sequence_.runPart(pixels.size(), time_,
                          [&](size_t i, WorkItem& item) { trace(pixels[i].first, pixels[i].second, item); });
    }

    // A band of rows at a time, for the progress report.
    void traceAll() {
        for (int top = 0; top < h_; top += kBand) {
            int bottom = std::min(h_, top + kBand);
            std::vector<std::pair<int, int>> pixels;
            for (int row = top; row < bottom; ++row)
                for (int x = 0; x < w_; ++x) pixels.push_back({x, row});
            traceEach(pixels);
            if (progress_) progress_->advance(long(pixels.size()), long(pixels.size()));
        }
    }

    // First pass on the grid; tiles whose corners differ are traced whole, the others interpolated.
    void adaptive() {
        const std::vector<int>&xs = xs_, &ys = ys_;
        std::vector<std::pair<int, int>> grid;
        for (int y : ys)
            for (int x : xs) grid.push_back({x, y});
        traceEach(grid);
        if (progress_) progress_->advance(long(grid.size()), long(grid.size()));
        std::vector<char> busy((xs.size() - 1) * (ys.size() - 1));
        for (size_t j = 0; j + 1 < ys.size(); ++j)
            for (size_t i = 0; i + 1 < xs.size(); ++i) {
                const float* c[4] = {colour(xs[i], ys[j]), colour(xs[i + 1], ys[j]), colour(xs[i], ys[j + 1]),
                                     colour(xs[i + 1], ys[j + 1])};
                bool b = false;
                for (int p = 0; p < 4 && !b; ++p)
                    for (int q = p + 1; q < 4 && !b; ++q) b = differ(c[p], c[q], s_.sampleThreshold);
                busy[j * (xs.size() - 1) + i] = b;
            }
        // Tile (i, j) spans columns xs[i]..xs[i+1] and rows ys[j]..ys[j+1], edges included: a pixel on an
        // edge is traced when any tile holding it is busy, else interpolated along the edge alone, which both
        // tiles agree on.
        std::vector<int> tileOfX(w_), tileOfY(h_);
        for (size_t i = 0; i + 1 < xs.size(); ++i) std::fill(&tileOfX[xs[i]], &tileOfX[xs[i + 1]] + 1, int(i));
        for (size_t j = 0; j + 1 < ys.size(); ++j) std::fill(&tileOfY[ys[j]], &tileOfY[ys[j + 1]] + 1, int(j));
        auto isBusy = [&](int x, int row) {
            size_t nx = xs.size() - 1;
            int i = tileOfX[x], j = tileOfY[row];
            bool b = busy[j * nx + i];
            if (i > 0 && x == xs[i]) b = b || busy[j * nx + i - 1];
            if (j > 0 && row == ys[j]) b = b || busy[(j - 1) * nx + i];
            if (i > 0 && j > 0 && x == xs[i] && row == ys[j]) b = b || busy[(j - 1) * nx + i - 1];
            return b;
        };
        for (int top = 0; top < h_; top += kBand) {
            int bottom = std::min(h_, top + kBand);
            std::vector<std::pair<int, int>> busyPixels;
            for (int row = top; row < bottom; ++row)
                for (int x = 0; x < w_; ++x)
                    if (!traced_[at(x, row)] && isBusy(x, row)) busyPixels.push_back({x, row});
            traceEach(busyPixels);
            for (int row = top; row < bottom; ++row)
                for (int x = 0; x < w_; ++x)
                    if (!traced_[at(x, row)])
                        interpolate(x, row, xs[tileOfX[x]], xs[tileOfX[x] + 1], ys[tileOfY[row]], ys[tileOfY[row] + 1]);
            if (progress_) progress_->advance(long(w_) * (bottom - top), long(busyPixels.size()));
        }
    }

    // Bilinear between the tile's traced corners (x0, y0)-(x1, y1).
    void interpolate(int x, int row, int x0, int x1, int y0, int y1) {
        double u = double(x - x0) / (x1 - x0), v = double(row - y0) / (y1 - y0);
        double wt[4] = {(1 - u) * (1 - v), u * (1 - v), (1 - u) * v, u * v};
        size_t corner[4] = {at(x0, y0), at(x1, y0), at(x0, y1), at(x1, y1)};
        float* p = pixel(x, row);
        float d = 0;
        for (int k = 0; k < 4; ++k) {
            const float* c = &values_.values[c_ * corner[k]];
            for (int ch = 0; ch < c_; ++ch) p[ch] += float(wt[k]) * c[ch];
            d += float(wt[k]) * depth_[corner[k]];
        }
        depth_[at(x, row)] = d;
    }

    Sequence& sequence_;
    const Integrator& integrator_;
    const View& view_;
    double time_;
    const PictureSettings& s_;
    ProgressMeter* progress_;
    static constexpr int kBand = 32;  // rows traced together
    int w_, h_, c_ = Spectrum::defaultChannels();
    PixelSpectra values_;
    std::vector<float> colours_;  // with bands: each traced pixel's RGB
    std::vector<float> depth_;
    std::vector<char> traced_;
    std::vector<int> xs_, ys_;  // the first pass's columns and rows
};

}  // namespace

void fitResolution(const View& view, PictureSettings& s) {
    normalizeResolution(view.aspect(), s.pixelAspect, s.xres, s.yres);
}

RenderedPicture renderPicture(Sequence& sequence, const View& view, double time, const PictureSettings& settings,
                              ProgressMeter* progress) {
    return Renderer(sequence, view, time, settings, progress).run();
}

}  // namespace brume
