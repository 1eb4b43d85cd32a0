// Facts from Radiance's oconv.c and bbox.c: the scene's bounds are those of its surfaces' vertices, spheres'
// axis extremes, cones' and rings' end circles, and the 8 transformed corners of each instance's octree
// cube and each mesh's cube, widened by OMARGIN (10 × FTINY = 1e-5) on each side; the cube has the largest extent as its size and
// is centred on the bounds; cubes smaller than size / resolution − FTINY are not divided. A cube divides when
// it would list more than the limit of objects, volumes (instances, meshes) that contain it not counted;
// children whose lists are all the same merge back into one leaf. Which objects meet a cube is decided
// here more loosely than oconv does, always erring toward listing an object, which only costs a tracer
// time: exactly for polygons and spheres, by the cube's circumscribed sphere for cones and rings, by their
// boxes for instances and meshes. Unlike oconv, a cube whose children would each list all of its objects
// is not divided: such a division gains nothing, and where more than the limit of loose boxes overlap it
// would go on to the resolution limit throughout a volume.
#include "world/octree_build.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <variant>

#include "geometry/bounds.h"
#include "world/scene_layout.h"
#include "world/scene_surfaces.h"

namespace brume {

namespace {

constexpr double kFtiny = 1e-6;  // Radiance's FTINY

enum class Contact { Miss, Hit, Inside };

struct Box {
    dvec3 center, half;
};

struct Triangle {
    dvec3 a, b, c;
};

struct Element {
    int object;
    Bounds3 bounds;  // by oconv's rule; decides the cube
    std::variant<std::monostate, std::vector<Triangle>, Sphere, Cone, Ring> shape;  // monostate: the bounds decide
    bool volume = false;                                                        // an instance or mesh
};

double largest(const dvec3& v) { return std::max({v.x, v.y, v.z}); }

dvec3 originOf(const OctreeCube& cube) { return {cube.origin[0], cube.origin[1], cube.origin[2]}; }

bool overlaps(const Bounds3& b, const Box& box) {
    for (int a = 0; a < 3; ++a)
        if (b.lo[a] > box.center[a] + box.half[a] || b.hi[a] < box.center[a] - box.half[a]) return false;
    return true;
}

bool within(const Box& box, const Bounds3& b) {
    return b.contains(box.center - box.half) && b.contains(box.center + box.half);
}

// Whether the plane n·p = offset passes through the box.
bool planeMeets(const dvec3& n, double offset, const Box& box) {
    double reach = glm::dot(glm::abs(n), box.half);
    return std::abs(glm::dot(n, box.center) - offset) <= reach;
}

// Separating-axis test of a triangle against a box: the box's axes, the triangle's normal and the nine
// cross products of their edges.
bool triangleMeets(const Triangle& t, const Box& box) {
    dvec3 v[3] = {t.a - box.center, t.b - box.center, t.c - box.center};
    dvec3 edges[3] = {v[1] - v[0], v[2] - v[1], v[0] - v[2]};
    auto separates = [&](const dvec3& axis) {
        double p0 = glm::dot(axis, v[0]), p1 = glm::dot(axis, v[1]), p2 = glm::dot(axis, v[2]);
        double reach = glm::dot(glm::abs(axis), box.half);
        return std::min({p0, p1, p2}) > reach || std::max({p0, p1, p2}) < -reach;
    };
    for (int a = 0; a < 3; ++a) {
        dvec3 axis(0);
        axis[a] = 1;
        if (separates(axis)) return false;
        for (const dvec3& e : edges)
            if (separates(glm::cross(axis, e))) return false;
    }
    return !separates(glm::cross(edges[0], edges[1]));
}

bool sphereSurfaceMeets(const Sphere& s, const Box& box) {
    dvec3 d = glm::abs(s.center - box.center);
    double nearest = glm::length(glm::max(d - box.half, dvec3(0))), farthest = glm::length(d + box.half);
    return nearest <= s.radius && farthest >= s.radius;
}

// The distance from point (x, y) to the segment from (x0, y0) to (x1, y1).
double segmentDistance(double x, double y, double x0, double y0, double x1, double y1) {
    double dx = x1 - x0, dy = y1 - y0, length2 = dx * dx + dy * dy;
    double t = length2 > 0 ? std::clamp(((x - x0) * dx + (y - y0) * dy) / length2, 0.0, 1.0) : 0;
    return std::hypot(x - x0 - t * dx, y - y0 - t * dy);
}

// A surface of revolution's outline is a segment in the plane of (distance along its axis, distance from it).
double axialDistance(const dvec3& p, const dvec3& origin, const dvec3& axis, double& along) {
    along = glm::dot(p - origin, axis);
    return glm::length(p - origin - along * axis);
}

double coneDistance(const Cone& c, const dvec3& p) {
    dvec3 axis = c.top - c.base;
    double length = glm::length(axis), along = 0;
    double radial = axialDistance(p, c.base, axis / length, along);
    return segmentDistance(along, radial, 0, c.baseRadius, length, c.topRadius);
}

double ringDistance(const Ring& r, const dvec3& p) {
    double along = 0, radial = axialDistance(p, r.center, r.normal, along);
    return segmentDistance(along, radial, 0, r.innerRadius, 0, r.outerRadius);
}

Contact contact(const Element& e, const Box& box) {
    if (!overlaps(e.bounds, box)) return Contact::Miss;
    if (e.volume) return within(box, e.bounds) ? Contact::Inside : Contact::Hit;
    bool meets = std::visit(
        [&](const auto& shape) {
            using T = std::decay_t<decltype(shape)>;
            if constexpr (std::is_same_v<T, std::vector<Triangle>>)
                return std::any_of(shape.begin(), shape.end(), [&](const Triangle& t) { return triangleMeets(t, box); });
            else if constexpr (std::is_same_v<T, Sphere>)
                return sphereSurfaceMeets(shape, box);
            else if constexpr (std::is_same_v<T, Cone>)
                return coneDistance(shape, box.center) <= glm::length(box.half);
            else if constexpr (std::is_same_v<T, Ring>)
                return planeMeets(shape.normal, glm::dot(shape.normal, shape.center), box) &&
                       ringDistance(shape, box.center) <= glm::length(box.half);
            else
                return true;
        },
        e.shape);
    return meets ? Contact::Hit : Contact::Miss;
}

// bbox.c's circle2bbox: a circle of radius r about `center`, facing the unit `axis`.
void includeCircle(Bounds3& b, const dvec3& center, const dvec3& axis, double r) {
    for (int a = 0; a < 3; ++a) {
        double reach = std::sqrt(1 - axis[a] * axis[a]) * r;
        b.lo[a] = std::min(b.lo[a], center[a] - reach);
        b.hi[a] = std::max(b.hi[a], center[a] + reach);
    }
}

// The cube oconv (and obj2mesh) puts around bounds: their largest extent, widened by the margin, centred.
OctreeCube cubeAround(Bounds3 b) {
    OctreeCube cube;
    if (b.empty()) return cube;
    b.lo -= kOctreeMargin, b.hi += kOctreeMargin;
    cube.size = largest(b.hi - b.lo);
    for (int a = 0; a < 3; ++a) cube.origin[a] = (b.hi[a] + b.lo[a] - cube.size) * .5;
    return cube;
}

// The cube of an instance's octree or a mesh: a compiled mesh's own, the one obj2mesh would give a
// Wavefront mesh.
OctreeCube fileCube(const PlacedFile& file) {
    if (!file.mesh) return file.cube;
    if (file.mesh->cubeSize > 0)
        return {{file.mesh->cubeOrigin.x, file.mesh->cubeOrigin.y, file.mesh->cubeOrigin.z}, file.mesh->cubeSize};
    Bounds3 b;
    for (const dvec3& v : file.mesh->vertices) b.include(v);
    return cubeAround(b);
}

// An instance or mesh: the box of its file's cube where the object places it.
Element volume(const Scene& scene, int index) {
    Element e{index, {}, {}, true};
    OctreeCube cube = fileCube(scene.placedFiles.at(scene.placedFileOf.at(index)));
    Transform t = objectTransform(scene.objects[index]);
    for (int corner = 0; corner < 8; ++corner) {
        dvec3 p = originOf(cube);
        for (int a = 0; a < 3; ++a)
            if (corner & (1 << a)) p[a] += cube.size;
        e.bounds.include(t.point(p));
    }
    return e;
}

std::optional<Element> surface(const Scene& scene, int index) {
    const SceneObject& o = scene.objects[index];
    std::optional<Surface> made = makeSurface(scene, index);
    Element e{index, {}, {}, false};
    if (o.type == "polygon") {
        for (size_t i = 0; i + 2 < o.reals.size(); i += 3) e.bounds.include(dvec3(o.reals[i], o.reals[i + 1], o.reals[i + 2]));
        if (!made) {  // degenerate: oconv bounds it all the same, and nothing can hit it
            e.shape = std::vector<Triangle>{};
            return e;
        }
        const Polygon& p = std::get<Polygon>(made->shape);
        std::vector<Triangle> triangles;
        for (const auto& [i, j, k] : p.triangles) triangles.push_back({p.vertices[i], p.vertices[j], p.vertices[k]});
        if (!triangles.empty()) e.shape = std::move(triangles);  // else its outline crosses itself: the box decides
        return e;
    }
    if (!made) return std::nullopt;
    if (const auto* s = std::get_if<Sphere>(&made->shape)) {
        e.bounds.include(s->center - s->radius);
        e.bounds.include(s->center + s->radius);
        e.shape = *s;
    } else if (const auto* c = std::get_if<Cone>(&made->shape)) {
        dvec3 axis = glm::normalize(c->top - c->base);
        includeCircle(e.bounds, c->base, axis, c->baseRadius);
        includeCircle(e.bounds, c->top, axis, c->topRadius);
        e.shape = *c;
    } else if (const auto* r = std::get_if<Ring>(&made->shape)) {
        includeCircle(e.bounds, r->center, r->normal, r->outerRadius);
        e.shape = *r;
    }
    return e;
}

std::vector<Element> elementsOf(const Scene& scene, size_t count) {
    std::vector<Element> elements;
    for (size_t i = 0; i < count; ++i) {
        const std::string& type = scene.objects[i].type;
        if (isSurfaceType(type)) {
            if (auto e = surface(scene, int(i))) elements.push_back(std::move(*e));
        } else if (type == "instance" || type == "mesh") {
            elements.push_back(volume(scene, int(i)));
        }
    }
    return elements;
}

OctreeCube cubeAround(const std::vector<Element>& elements) {
    Bounds3 b;
    for (const Element& e : elements) b.include(e.bounds);
    return cubeAround(b);
}

// The elements that meet a cube, and how many of them count toward dividing it (those not containing it).
struct Meeting {
    std::vector<int> met;
    size_t counted = 0;
};

class Builder {
public:
    Builder(const std::vector<Element>& elements, const OctreeBuildOptions& options, double rootSize)
        : elements_(elements),
          limit_(options.objectLimit),
          minSize_(rootSize / options.resolution - kFtiny),
          slack_(1e-7 * rootSize) {}

    // The elements among `candidates` that meet the cube at `origin` of `size`.
    Meeting meeting(const dvec3& origin, double size, const std::vector<int>& candidates) const {
        Box box{origin + size / 2, dvec3(size / 2 + slack_)};
        Meeting m;
        for (int c : candidates) {
            Contact k = contact(elements_[c], box);
            if (k == Contact::Miss) continue;
            m.met.push_back(c);
            m.counted += k == Contact::Hit;
        }
        return m;
    }

    // Appends the nodes of the cube at `origin` of `size`, which the elements of `here` meet.
    void build(const dvec3& origin, double size, const Meeting& here) {
        double half = size / 2;
        if (here.counted <= limit_ || half < minSize_) return leaf(here.met);
        std::array<Meeting, 8> children;
        bool gains = false;  // dividing gains nothing unless some child meets fewer
        for (int child = 0; child < 8; ++child) {
            children[child] = meeting(childOrigin(origin, half, child), half, here.met);
            gains = gains || children[child].met.size() < here.met.size();
        }
        if (!gains) return leaf(here.met);
        size_t at = built.nodes.size();
        built.nodes.push_back({true, {}});
        for (int child = 0; child < 8; ++child) build(childOrigin(origin, half, child), half, children[child]);
        mergeAlike(at);
    }

    BuiltOctree built;

private:
    static dvec3 childOrigin(dvec3 origin, double half, int child) {
        for (int a = 0; a < 3; ++a)
            if (child & (1 << a)) origin[a] += half;
        return origin;
    }

    void leaf(const std::vector<int>& met) {
        OctreeNode node;
        for (int m : met) node.set.push_back(elements_[m].object);
        if (node.set.size() > kMaxOctreeSet) {
            if (built.overflowObject < 0) built.overflowObject = node.set[kMaxOctreeSet];
            node.set.resize(kMaxOctreeSet);
        }
        built.nodes.push_back(std::move(node));
    }

    // A tree node at `at` whose eight children are leaves listing the same objects becomes that leaf.
    void mergeAlike(size_t at) {
        std::vector<OctreeNode>& nodes = built.nodes;
        if (nodes.size() != at + 9) return;
        for (size_t i = at + 1; i < at + 9; ++i)
            if (nodes[i].tree || nodes[i].set != nodes[at + 1].set) return;
        nodes[at] = std::move(nodes[at + 1]);
        nodes.resize(at + 1);
    }

    const std::vector<Element>& elements_;
    size_t limit_;
    double minSize_, slack_;
};

void requireWithin(const OctreeCube& cube, const std::vector<Element>& elements, const Scene& scene) {
    Bounds3 box{originOf(cube), originOf(cube) + cube.size};
    for (const Element& e : elements)
        if (!box.contains(e.bounds.lo) || !box.contains(e.bounds.hi))
            throw Error(scene.objects[e.object].where, "boundary does not encompass scene (" +
                                                           scene.objects[e.object].type + " \"" +
                                                           scene.objects[e.object].name + "\" is outside it)");
}

}  // namespace

BuiltOctree buildOctree(const Scene& scene, size_t count, const OctreeBuildOptions& options) {
    std::vector<Element> elements = elementsOf(scene, count);
    OctreeCube cube = options.cube ? *options.cube : cubeAround(elements);
    if (options.cube) requireWithin(cube, elements, scene);
    std::vector<int> all(elements.size());
    for (size_t i = 0; i < all.size(); ++i) all[i] = int(i);
    Builder builder(elements, options, cube.size);
    builder.build(originOf(cube), cube.size, builder.meeting(originOf(cube), cube.size, all));
    builder.built.cube = cube;
    return std::move(builder.built);
}

}  // namespace brume
