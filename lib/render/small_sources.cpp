#include "render/small_sources.h"

#include <algorithm>
#include <cmath>

namespace brume {

namespace {

using Point = glm::dvec2;
using Outline = std::vector<Point>;

double cross(const Point& o, const Point& a, const Point& b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The convex hull, counter-clockwise (Andrew's monotone chain).
Outline convexHull(Outline p) {
    std::sort(p.begin(), p.end(), [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (p.size() < 3) return p;
    Outline h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); h[k++] = p[i++])
        while (k >= 2 && cross(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    for (size_t i = p.size() - 1, t = k + 1; i > 0; h[k++] = p[--i])
        while (k >= t && cross(h[k - 2], h[k - 1], p[i - 1]) <= 0) --k;
    h.resize(k - 1);
    return h;
}

// Sutherland–Hodgman against the box [x0, x1] × [y0, y1].
Outline clipToBox(const Outline& in, double x0, double x1, double y0, double y1) {
    Outline poly = in;
    auto clip = [&poly](auto inside, auto meet) {
        Outline out;
        for (size_t i = 0; i < poly.size(); ++i) {
            const Point &a = poly[i], &b = poly[(i + 1) % poly.size()];
            if (inside(a)) out.push_back(a);
            if (inside(a) != inside(b)) out.push_back(meet(a, b));
        }
        poly = std::move(out);
    };
    auto atX = [](double x) {
        return [x](const Point& a, const Point& b) { return Point(x, a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x)); };
    };
    auto atY = [](double y) {
        return [y](const Point& a, const Point& b) { return Point(a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y), y); };
    };
    clip([x0](const Point& p) { return p.x >= x0; }, atX(x0));
    clip([x1](const Point& p) { return p.x <= x1; }, atX(x1));
    clip([y0](const Point& p) { return p.y >= y0; }, atY(y0));
    clip([y1](const Point& p) { return p.y <= y1; }, atY(y1));
    return poly;
}

// Area and centroid of a simple polygon.
double areaAndCentroid(const Outline& p, Point& centroid) {
    double a = 0;
    Point c(0);
    for (size_t i = 0; i < p.size(); ++i) {
        const Point &u = p[i], &v = p[(i + 1) % p.size()];
        double w = u.x * v.y - v.x * u.y;
        a += w;
        c += w * (u + v);
    }
    if (std::abs(a) < 1e-300) return 0;
    centroid = c / (3 * a);
    return std::abs(a) / 2;
}

// The narrowest width of a convex polygon: over its edges, the farthest vertex from each edge's line.
double minimumWidth(const Outline& p) {
    double width = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < p.size(); ++i) {
        const Point &a = p[i], &b = p[(i + 1) % p.size()];
        double len = glm::length(b - a), farthest = 0;
        if (!(len > 0)) continue;
        for (const Point& q : p) farthest = std::max(farthest, std::abs(cross(a, b, q)) / len);
        width = std::min(width, farthest);
    }
    return width;
}

// The source's outline in pixel coordinates (x right, y up from the bottom edge), clipped to the picture;
// empty if any of it is behind the view.
Outline pixelOutline(const Light& light, const View& view, int w, int h) {
    Outline points;
    for (const dvec3& p : light.outline(view.vp)) {
        auto at = view.location(p);
        if (!at) return {};
        points.push_back({at->x * w, at->y * h});
    }
    if (points.size() < 3) return {};
    return clipToBox(convexHull(points), 0, w, 0, h);
}

void drawSource(const Integrator& integrator, WorkItem& item, double time, const Light& light, const View& view,
                const Outline& outline, PixelSpectra& picture, std::vector<float>* depth) {
    int w = picture.width, h = picture.height;
    double x0 = w, x1 = 0, y0 = h, y1 = 0;
    for (const Point& p : outline) x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    for (int y = std::max(0, int(y0)); y <= std::min(h - 1, int(y1)); ++y)
        for (int x = std::max(0, int(x0)); x <= std::min(w - 1, int(x1)); ++x) {
            Point centre;
            double covered = areaAndCentroid(clipToBox(outline, x, x + 1, y, y + 1), centre);
            if (!(covered > 0)) continue;
            auto ray = view.ray(centre.x / w, centre.y / h);
            if (!ray) continue;
            int row = h - 1 - y;
            // Seeded apart from the picture's own pixels (whose indices run below w·h).
            uint64_t index = uint64_t(w) * h * (2 + uint64_t(light.object())) + uint64_t(row) * w + x;
            RayRecord rec =
                integrator.trace({ray->org, ray->dir, index, time, std::isfinite(ray->tmax) ? ray->tmax : 0}, item);
            if (rec.surfaceObject != light.object() || !(brightness(rec.value) > 0)) continue;  // blocked, or dark here
            float* pixel = picture.at(x, row);
            size_t i = size_t(row) * w + x;
            bool nearer = depth && rec.effectiveLength < 0.99 * (*depth)[i];
            if (nearer) (*depth)[i] = float(rec.effectiveLength);
            // Radiance's rule: a pixel whose own ray found the source already holds its radiance, scaled to the part
            // covered; otherwise the source's share replaces that much of the pixel.
            bool sameAsSource = true;
            int n = picture.channels;
            for (int c = 0; c < n; ++c) sameAsSource &= std::abs(pixel[c] - rec.value[c]) <= 0.07f * std::min(pixel[c], rec.value[c]);
            for (int c = 0; c < n; ++c)
                pixel[c] = sameAsSource && !nearer ? float(covered) * pixel[c]
                                                   : float(1 - covered) * pixel[c] + float(covered) * rec.value[c];
        }
}

}  // namespace

void drawSmallSources(const Integrator& integrator, double time, const View& view, double widthLimit,
                      PixelSpectra& picture, std::vector<float>* depth) {
    Scratch scratch(integrator.scene());
    WorkItem item{scratch};
    for (const Light& light : integrator.scene().lights()) {
        if (light.emitter().kind == Emitter::Kind::Illum) continue;
        if (light.isDistant() && view.type == kParallel) continue;  // a parallel view sees all of it or none
        Outline outline = pixelOutline(light, view, picture.width, picture.height);
        if (outline.size() < 3 || minimumWidth(outline) > widthLimit) continue;
        drawSource(integrator, item, time, light, view, outline, picture, depth);
    }
}

}  // namespace brume
