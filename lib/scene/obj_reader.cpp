// Wavefront .obj files read straight into a mesh, with the rules of Radiance's obj2mesh (facts from its
// wfconv.c, cvmesh.c and tmesh.c): a vertex is a distinct position/texture/normal triple; vertex normals are
// normalized, and dropped from triangles they do not bend (all within 0.999995 in cosine of the face
// normal); a triangle whose normals all point behind it is turned around; polygons are triangulated with
// the winding of their outline; zero-area triangles are dropped.
#include <cctype>
#include <charconv>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <optional>
#include <unordered_map>

#include "geometry/polygon.h"
#include "scene/mesh.h"
#include "util/error.h"

namespace brume {

namespace {

constexpr double kFlatCosine = 0.999995;  // obj2mesh's COSTOL
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One corner of a face: indices of its position, texture coordinates and normal (-1: none).
struct Corner {
    int v, vt, vn;
    bool operator==(const Corner&) const = default;
};

struct CornerHash {
    size_t operator()(const Corner& c) const {
        return std::hash<uint64_t>()((uint64_t(uint32_t(c.v)) << 32) ^ (uint64_t(uint32_t(c.vt)) << 16) ^
                                     uint32_t(c.vn));
    }
};

void split(const std::string& text, std::vector<std::string>& words) {
    auto space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
    for (size_t i = 0; i < text.size();) {
        while (i < text.size() && space(text[i])) ++i;
        size_t start = i;
        while (i < text.size() && !space(text[i])) ++i;
        if (i > start) words.emplace_back(text, start, i - start);
    }
}

std::optional<double> number(const std::string& s) {
    double x;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), x);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(x)) return std::nullopt;
    return x;
}

class WavefrontReader {
public:
    WavefrontReader(std::istream& in, std::string name, const MaterialLookup& lookup)
        : in_(in), name_(std::move(name)), lookup_(lookup) {}

    Mesh read() {
        std::vector<std::string> words;
        while (nextStatement(words)) statement(words);
        if (unrecognized_ > 0)
            warn(name_ + ": " + std::to_string(unrecognized_) + " of " + std::to_string(statements_) +
                 " statements unrecognized");
        if (mesh_.triangles.empty()) throw Error(SourceLocation{name_}, "no faces in mesh");
        if (!anyNormal_) mesh_.normals = {};
        if (!anyUv_) mesh_.uvs = {};
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail(const std::string& what) const { throw Error(SourceLocation{name_, line_}, what); }

    // The words of the next statement that has any (a backslash ends a line that goes on).
    bool nextStatement(std::vector<std::string>& words) {
        words.clear();
        for (std::string text; words.empty() && std::getline(in_, text);) {
            ++line_;
            while (!text.empty() && (text.back() == '\\' || text.back() == '\r')) {
                bool more = text.back() == '\\';
                text.pop_back();
                std::string next;
                if (more && std::getline(in_, next)) ++line_, text += " " + next;
            }
            split(text, words);
        }
        return !words.empty();
    }

    void statement(const std::vector<std::string>& w) {
        const std::string& k = w[0];
        if (k[0] == '#') return;
        ++statements_;
        if (k == "v")
            positions_.push_back(vector3(w, "bad vertex"));
        else if (k == "vn")
            normal(w);
        else if (k == "vt")
            texture(w);
        else if (k == "f")
            face(w);
        else if (k == "usemtl")
            material_ = w.size() > 1 ? w[1] : "";
        else if (k == "g")
            group_ = w.size() > 1 ? w[1] : "";
        else if (k != "usemap" && k != "o")
            ++unrecognized_;
    }

    // Three numbers, within ±1e18 (where rays can be traced).
    glm::dvec3 vector3(const std::vector<std::string>& w, const char* what) const {
        if (w.size() < 4) fail(what);
        glm::dvec3 v;
        for (int i = 0; i < 3; ++i) {
            auto x = number(w[i + 1]);
            if (!x || std::abs(*x) > 1e18) fail(what);
            v[i] = *x;
        }
        return v;
    }

    void normal(const std::vector<std::string>& w) {
        glm::dvec3 n = vector3(w, "bad normal");
        if (!(glm::length(n) > 0)) fail("zero normal");
        normals_.push_back(glm::vec3(glm::normalize(n)));
    }

    // vt u [v [w]]: v is 0 when not given.
    void texture(const std::vector<std::string>& w) {
        glm::dvec2 uv(0);
        for (size_t i = 1; i < std::min<size_t>(w.size(), 3); ++i) {
            auto x = number(w[i]);
            if (!x) fail("bad texture coordinate");
            uv[i - 1] = *x;
        }
        if (w.size() < 2) fail("bad texture coordinate");
        textures_.push_back(uv);
    }

    // One index of a corner: 1-based, or negative counting back from the last one given; 0 or empty is none.
    int index(std::string_view s, size_t count, bool required) const {
        long i = 0;
        if (!s.empty()) {
            auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), i);
            if (ec != std::errc() || end != s.data() + s.size()) fail("bad vertex reference");
        }
        if (i == 0 && !required) return -1;
        long resolved = i > 0 ? i - 1 : long(count) + i;
        if (i == 0 || resolved < 0 || resolved >= long(count)) fail("bad vertex reference");
        return int(resolved);
    }

    Corner corner(std::string_view s) const {
        size_t a = s.find('/'), b = a == std::string_view::npos ? a : s.find('/', a + 1);
        auto part = [&](size_t from, size_t to) {
            return from == std::string_view::npos
                       ? std::string_view()
                       : s.substr(from + 1, to == std::string_view::npos ? to : to - from - 1);
        };
        return {index(s.substr(0, a), positions_.size(), true), index(part(a, b), textures_.size(), false),
                index(part(b, std::string_view::npos), normals_.size(), false)};
    }

    void face(const std::vector<std::string>& w) {
        if (w.size() < 4) fail("too few vertices");
        std::vector<Corner> corners;
        for (size_t i = 1; i < w.size(); ++i) {
            Corner c = corner(w[i]);
            if (corners.empty() || positions_[c.v] != positions_[corners.back().v]) corners.push_back(c);
        }
        while (corners.size() > 1 && positions_[corners.front().v] == positions_[corners.back().v]) corners.pop_back();
        if (corners.size() < 3) return;
        int material = currentMaterial();
        if (corners.size() == 3) return triangle(corners[0], corners[1], corners[2], material);
        polygon(corners, material);
    }

    void polygon(const std::vector<Corner>& corners, int material) {
        std::vector<glm::dvec3> outline;
        for (const Corner& c : corners) outline.push_back(positions_[c.v]);
        std::string why;
        auto poly = makePolygon(outline, why);
        if (!poly) return;  // no area
        auto triangles = triangulate(*poly);
        if (triangles.empty()) warn(SourceLocation{name_, line_}.str() + ": self-intersecting face dropped");
        for (auto t : triangles) {
            const auto& v = poly->vertices;
            if (glm::dot(glm::cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]), poly->normal) < 0) std::swap(t[1], t[2]);
            triangle(corners[t[0]], corners[t[1]], corners[t[2]], material);
        }
    }

    // obj2mesh's material: the usemtl name, else the group name; void without a lookup or a name.
    int currentMaterial() {
        const std::string& name = material_.empty() ? group_ : material_;
        if (!lookup_ || name.empty() || name == "void") return -1;
        auto [it, added] = materials_.try_emplace(name, -1);
        if (added) it->second = lookup_(name);
        if (it->second < 0) fail("undefined modifier \"" + name + "\"");
        return it->second;
    }

    void triangle(Corner a, Corner b, Corner c, int material) {
        const glm::dvec3 &pa = positions_[a.v], &pb = positions_[b.v], &pc = positions_[c.v];
        glm::dvec3 n = glm::cross(pb - pa, pc - pb);
        if (!(glm::length(n) > 0)) return;
        n = glm::normalize(n);
        if (a.vt < 0 || b.vt < 0 || c.vt < 0) a.vt = b.vt = c.vt = -1;
        if (a.vn < 0 || b.vn < 0 || c.vn < 0) a.vn = b.vn = c.vn = -1;
        if (a.vn >= 0) {
            double d[3] = {glm::dot(n, glm::dvec3(normals_[a.vn])), glm::dot(n, glm::dvec3(normals_[b.vn])),
                           glm::dot(n, glm::dvec3(normals_[c.vn]))};
            bool behind = d[0] < 0 && d[1] < 0 && d[2] < 0;
            bool flat =
                behind ? std::max({d[0], d[1], d[2]}) <= -kFlatCosine : std::min({d[0], d[1], d[2]}) >= kFlatCosine;
            if (flat) a.vn = b.vn = c.vn = -1;
            if (behind) std::swap(a, c);
        }
        mesh_.triangles.push_back({vertex(a), vertex(b), vertex(c)});
        mesh_.materials.push_back(material);
    }

    uint32_t vertex(const Corner& c) {
        auto [it, added] = vertices_.try_emplace(c, uint32_t(mesh_.vertices.size()));
        if (!added) return it->second;
        mesh_.vertices.push_back(positions_[c.v]);
        mesh_.normals.push_back(c.vn >= 0 ? normals_[c.vn] : glm::vec3(0));
        mesh_.uvs.push_back(c.vt >= 0 ? textures_[c.vt] : glm::dvec2(kNaN));
        anyNormal_ = anyNormal_ || c.vn >= 0;
        anyUv_ = anyUv_ || c.vt >= 0;
        return it->second;
    }

    std::istream& in_;
    std::string name_;
    const MaterialLookup& lookup_;
    int line_ = 0, statements_ = 0, unrecognized_ = 0;
    std::vector<glm::dvec3> positions_;
    std::vector<glm::vec3> normals_;
    std::vector<glm::dvec2> textures_;
    std::string material_, group_;
    std::unordered_map<std::string, int> materials_;
    std::unordered_map<Corner, uint32_t, CornerHash> vertices_;
    bool anyNormal_ = false, anyUv_ = false;
    Mesh mesh_;
};

}  // namespace

Mesh readWavefront(std::istream& in, const std::string& name, const MaterialLookup& lookup) {
    return WavefrontReader(in, name, lookup).read();
}

bool isWavefrontName(const std::string& path) {
    if (path.size() < 4) return false;
    std::string ext = path.substr(path.size() - 4);
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".obj";
}

}  // namespace brume
