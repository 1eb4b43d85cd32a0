#include "render/picture_renderer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

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
        settled_.assign(size_t(w_) * h_, 0);
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

    // One ray through pixel (x, row): its value and distance stored.
    void trace(int x, int row, WorkItem& item) {
        size_t i = at(x, row);
        uint64_t index = i;
        Random random(integrator_.seedFor(index) ^ 0x6a09e667f3bcc909ULL, index);  // this pixel's jitter and lens
        double jx = 0.5 + s_.jitter * (0.5 - random.uniform()), jy = 0.5 + s_.jitter * (0.5 - random.uniform());
        // The view's y runs up from the bottom edge; rows run down from the top.
        std::optional<ViewRay> ray = view_.ray((x + jx) / w_, (h_ - 1 - row + jy) / h_);
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

    // A block of pixels whose corners are traced: a tile of the first pass (level 1) or a quarter of a block.
    struct Block {
        int x0, y0, x1, y1, level;
        bool hasInterior() const { return x1 - x0 > 1 || y1 - y0 > 1; }
    };

    // As Radiance's rpict: the first pass on the grid; a block whose corners differ has its middle and the
    // middles of its edges traced and is split in four, level by level, until its quarters' corners agree or
    // are neighbours; the pixels left are interpolated from the corners of the finest block holding them.
    // A smooth gradient costs five samples per tile, not the whole tile; an edge, the pixels along it.
    void adaptive() {
        const std::vector<int>&xs = xs_, &ys = ys_;
        std::vector<std::pair<int, int>> grid;
        for (int y : ys)
            for (int x : xs) grid.push_back({x, y});
        queue(grid);
        traceEach(grid);
        if (progress_) progress_->advance(long(grid.size()), long(grid.size()));
        // Bands of tile rows, for the progress report.
        size_t tileRows = std::max<size_t>(1, kBand / s_.sampleSpacing);
        for (size_t j0 = 0; j0 + 1 < ys.size(); j0 += tileRows) {
            size_t j1 = std::min(ys.size() - 1, j0 + tileRows);
            std::vector<Block> open;
            for (size_t j = j0; j < j1; ++j)
                for (size_t i = 0; i + 1 < xs.size(); ++i) open.push_back({xs[i], ys[j], xs[i + 1], ys[j + 1], 1});
            long traced = 0;
            while (!open.empty()) {
                std::vector<Block> finer;
                std::vector<std::pair<int, int>> middles;
                for (const Block& b : open) {
                    if (!b.hasInterior()) continue;
                    if (cornersDiffer(b)) split(b, finer, middles);
                    else fill(b);
                }
                traceEach(middles);
                traced += long(middles.size());
                open = std::move(finer);
            }
            int bottom = j1 + 1 == ys.size() ? h_ : ys[j1];
            if (progress_) progress_->advance(long(w_) * (bottom - ys[j0]), traced);
        }
    }

    // Colours too different to interpolate, or distances: an object in front of another (a chair leg before the
    // floor) may have the same colour at the corners and another between them.
    bool cornersDiffer(const Block& b) {
        size_t i[4] = {at(b.x0, b.y0), at(b.x1, b.y0), at(b.x0, b.y1), at(b.x1, b.y1)};
        const float* c[4] = {colour(b.x0, b.y0), colour(b.x1, b.y0), colour(b.x0, b.y1), colour(b.x1, b.y1)};
        for (int p = 0; p < 4; ++p)
            for (int q = p + 1; q < 4; ++q) {
                float zp = depth_[i[p]], zq = depth_[i[q]];
                if (differ(c[p], c[q], s_.sampleThreshold) || 2 * std::abs(zp - zq) > s_.sampleThreshold * (zp + zq))
                    return true;
            }
        return false;
    }

    // Queues the middles of b's edges and its centre that are not yet traced; adds its quarters (halves
    // where it is one pixel across) to `finer`.
    void split(const Block& b, std::vector<Block>& finer, std::vector<std::pair<int, int>>& middles) {
        auto cuts = [](int a, int z) {
            return z - a > 1 ? std::vector<int>{a, (a + z) / 2, z} : std::vector<int>{a, z};
        };
        std::vector<int> cx = cuts(b.x0, b.x1), cy = cuts(b.y0, b.y1);
        std::vector<std::pair<int, int>> points;
        for (int y : cy)
            for (int x : cx) points.push_back({x, y});
        queue(points, &middles);
        for (size_t j = 0; j + 1 < cy.size(); ++j)
            for (size_t i = 0; i + 1 < cx.size(); ++i) finer.push_back({cx[i], cy[j], cx[i + 1], cy[j + 1], b.level + 1});
    }

    // Marks the pixels listed as traced (they are about to be); with `fresh`, adds those not traced before.
    void queue(const std::vector<std::pair<int, int>>& pixels, std::vector<std::pair<int, int>>* fresh = nullptr) {
        for (const auto& [x, row] : pixels) {
            uint8_t& s = settled_[at(x, row)];
            if (s == kTraced) continue;
            s = kTraced;
            if (fresh) fresh->push_back({x, row});
        }
    }

    // The untraced pixels of a block whose corners agree, unless a finer block already interpolated them.
    void fill(const Block& b) {
        for (int row = b.y0; row <= b.y1; ++row)
            for (int x = b.x0; x <= b.x1; ++x) {
                uint8_t& s = settled_[at(x, row)];
                if (s == kTraced || s > b.level) continue;
                s = uint8_t(b.level);
                interpolate(x, row, b.x0, b.x1, b.y0, b.y1);
            }
    }

    // Bilinear between the block's traced corners (x0, y0)-(x1, y1).
    void interpolate(int x, int row, int x0, int x1, int y0, int y1) {
        double u = double(x - x0) / (x1 - x0), v = double(row - y0) / (y1 - y0);
        double wt[4] = {(1 - u) * (1 - v), u * (1 - v), (1 - u) * v, u * v};
        size_t corner[4] = {at(x0, y0), at(x1, y0), at(x0, y1), at(x1, y1)};
        float* p = pixel(x, row);
        std::fill_n(p, c_, 0.f);
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
    // Per pixel: kTraced, or the level of the block it was interpolated in (0: neither yet).
    std::vector<uint8_t> settled_;
    static constexpr uint8_t kTraced = 255;
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
