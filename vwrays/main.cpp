// vwrays: the ray of every pixel of a view or picture, for rtrace, as Radiance's vwrays (see man/vwrays.1).
#include <sys/stat.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <vector>

#include "io/resolution.h"
#include "sampling/random.h"
#include "util/error.h"
#include "util/options.h"
#include "view/aperture.h"
#include "view/pixel_aspect.h"
#include "view/view_file.h"
#include "view/view_options.h"

using namespace brume;

namespace {

const std::string kUsage =
    "Usage: vwrays [ -i -u -f{a|f|d} -c rept | -d ] { view opts .. | picture [zbuf] }\n";

struct Options {
    View view;
    Resolution resolution{512, 512};
    double pixelAspect = 1, pixelJitter = 0, aperture = 0;
    char format = 'a';
    bool dimensionsOnly = false, fromInput = false, unbuffered = false;
    int count = 1;
};

OptionTable makeTable(Options& o) {
    OptionTable t;
    t.addAttached("-f", "output format: a (ascii), f (float), d (double)", [&o](const std::string& v) {
        if (v.size() != 1 || std::string("afd").find(v[0]) == std::string::npos) throw Error("bad format '-f" + v + "'");
        o.format = v[0];
    });
    addViewOptions(t, o.view);
    auto resolution = [](const char* axis, int& out) {
        return [axis, &out](const std::vector<std::string>& a) {
            out = toInt(std::string("-") + axis, a[0]);
            if (out <= 0) throw Error(std::string("bad ") + axis + " resolution");
        };
    };
    t.add("-x", 1, "x resolution", resolution("x", o.resolution.width));
    t.add("-y", 1, "y resolution", resolution("y", o.resolution.height));
    t.add("-pa", 1, "pixel aspect (height/width); 0 keeps -x and -y",
          [&o](const auto& a) { o.pixelAspect = toReal("-pa", a[0]); });
    t.add("-pj", 1, "pixel jitter (0 to 1)", [&o](const auto& a) { o.pixelJitter = toReal("-pj", a[0]); });
    t.add("-pd", 1, "aperture diameter for depth of field", [&o](const auto& a) { o.aperture = toReal("-pd", a[0]); });
    t.add("-c", 1, "rays per pixel", [&o](const auto& a) { o.count = std::max(1, toInt("-c", a[0])); });
    t.add("-d", 0, "print the resolution options for rtrace and stop", [&o](const auto&) { o.dimensionsOnly = true; });
    t.add("-i", 0, "read pixel positions (x y from the bottom left) from the standard input",
          [&o](const auto&) { o.fromInput = true; });
    t.add("-u", 0, "flush after each input pixel", [&o](const auto&) { o.unbuffered = true; });
    return t;
}

// Writes one ray in the chosen format; a pixel without a ray is six zeros.
class RayWriter {
public:
    explicit RayWriter(char format) : format_(format) {}
    void put(const dvec3& org, const dvec3& dir) const {
        if (format_ == 'a') {
            std::printf("%.5e %.5e %.5e %.5e %.5e %.5e\n", org.x, org.y, org.z, dir.x, dir.y, dir.z);
        } else if (format_ == 'f') {
            float v[6] = {float(org.x), float(org.y), float(org.z), float(dir.x), float(dir.y), float(dir.z)};
            std::fwrite(v, sizeof v, 1, stdout);
        } else {
            double v[6] = {org.x, org.y, org.z, dir.x, dir.y, dir.z};
            std::fwrite(v, sizeof v, 1, stdout);
        }
    }

private:
    char format_;
};

// The rays of one pixel: jittered over the pixel (-pj, stratified when -c gives several) and the lens
// (-pd), from a generator seeded by the pixel's number so that the output repeats exactly.
class PixelRays {
public:
    PixelRays(const Options& o, const RayWriter& writer, const std::vector<float>& depth)
        : o_(o), writer_(writer), depth_(depth) {}

    // The rays through image point (x, y) (0 to 1 from the bottom left), whose depth (if a depth buffer
    // was given) is at `depthIndex`.
    void put(double x, double y, uint64_t pixel, long depthIndex) const {
        Random random(mixBits(pixel), 0);
        uint64_t scramble = (uint64_t(random.next()) << 32) | random.next();
        for (int c = 0; c < o_.count; ++c) {
            double u = random.uniform(), v = random.uniform();
            if (o_.count > 1) sobol2D(uint32_t(c), scramble, u, v);
            double jx = x, jy = y;
            if (o_.pixelJitter > 1e-6) {
                jx += o_.pixelJitter * (.5 - u) / o_.resolution.width;
                jy += o_.pixelJitter * (.5 - v) / o_.resolution.height;
            }
            putRay(jx, jy, random, depthIndex);
        }
    }

private:
    void putRay(double x, double y, Random& random, long depthIndex) const {
        auto ray = o_.view.ray(x, y);
        if (ray && o_.aperture > 1e-6) {
            double u1 = random.uniform(), u2 = random.uniform(), u3 = random.uniform();
            if (!jitterAperture(o_.view, *ray, o_.aperture, u1, u2, u3)) ray.reset();
        }
        if (!ray) return writer_.put(dvec3(0), dvec3(0));
        if (!depth_.empty()) {
            // The surface point seen, and the direction light leaves it towards the pixel.
            double z = depth_[size_t(depthIndex)];
            return writer_.put(ray->org + z * ray->dir, -(o_.fromInput ? 1 : z) * ray->dir);
        }
        // With an aft clipping plane, the direction's length says how far to look (rtrace -ld+).
        double scale = std::isfinite(ray->tmax) && ray->tmax > 1e-6 ? ray->tmax : 1;
        writer_.put(ray->org, scale * ray->dir);
    }

    const Options& o_;
    const RayWriter& writer_;
    const std::vector<float>& depth_;
};

// Every pixel, in the order of the picture's scanlines (top to bottom for a view).
void putAllPixels(const Options& o, const PixelRays& rays) {
    const Resolution& r = o.resolution;
    for (int s = 0; s < r.scanlines(); ++s)
        for (int k = 0; k < r.scanlineLength(); ++k) {
            auto [x, y] = r.pixel(s, k);
            long index = long(s) * r.scanlineLength() + k;
            rays.put((x + .5) / r.width, (r.height - 1 - y + .5) / r.height, uint64_t(index), index);
        }
}

// Pixel positions "x y" from the standard input, measured from the bottom left corner.
void putInputPixels(const Options& o, const PixelRays& rays, bool withDepth) {
    const Resolution& r = o.resolution;
    double px, py;
    for (uint64_t n = 0; std::cin >> px >> py; ++n) {
        double x = (px + .5) / r.width, y = (py + .5) / r.height;
        long index = 0;
        if (withDepth) {
            if (x < 0 || x >= 1 || y < 0 || y >= 1) throw Error("input pixel outside image");
            index = r.storedIndex(int(x * r.width), r.height - 1 - int(y * r.height));
        }
        rays.put(x, y, n, index);
        if (o.unbuffered) std::fflush(stdout);
    }
    if (!std::cin.eof()) throw Error("expected px py on input");
}

// A depth buffer: raw native floats, one per pixel in the picture's scan order.
std::vector<float> readDepth(const std::string& path, const Resolution& r) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open for reading");
    char magic[2] = {};
    in.read(magic, 2);
    if (in.gcount() == 2 && magic[0] == '#' && magic[1] == '?')
        throw Error(path + ": encoded depth files (rcode_depth) are not supported by Brume yet; decode with rcode_depth -r");
    in.seekg(0, std::ios::end);
    long expected = long(r.width) * r.height, actual = long(in.tellg() / std::streamoff(sizeof(float)));
    if (actual != expected || in.tellg() % std::streamoff(sizeof(float)))
        throw Error(path + ": expected length is " + std::to_string(expected) + ", actual length is " +
                    std::to_string(actual));
    std::vector<float> depth(static_cast<size_t>(expected));
    in.seekg(0);
    in.read(reinterpret_cast<char*>(depth.data()), std::streamsize(depth.size() * sizeof(float)));
    return depth;
}

int run(int argc, char** argv) {
    std::ios::sync_with_stdio(false);
    setProgramName(argv[0]);
    Options o;
    OptionTable table = makeTable(o);
    if (argc < 2) throw UsageError("no view options or picture", kUsage + table.usage());
    std::vector<std::string> args = operandsAfterOptions(table, argc, argv, kUsage);
    if (args.size() > 2) throw UsageError("too many arguments", kUsage + table.usage());
    bool picture = !args.empty();
    std::vector<float> depth;
    if (picture) {
        if (!readViewFile(args[0], o.view, &o.resolution)) throw Error(args[0] + ": no view in picture");
        if (!o.dimensionsOnly && args.size() > 1) depth = readDepth(args[1], o.resolution);
    }
    o.view.validate();
    if (!picture) normalizeResolution(o.view.aspect(), o.pixelAspect, o.resolution.width, o.resolution.height);
    if (o.dimensionsOnly) {
        std::printf("-x %d -y %d%s\n", o.resolution.width, o.resolution.height, o.view.va > 1e-6 ? " -ld+" : "");
        return 0;
    }
    RayWriter writer(o.format);
    PixelRays rays(o, writer, depth);
    if (o.fromInput) putInputPixels(o, rays, !depth.empty());
    else putAllPixels(o, rays);
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    return runReportingErrors([&] { return run(argc, argv); });
}
