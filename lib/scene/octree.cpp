// The octree format, as Radiance's oconv writes it (facts from its writeoct.c, sceneio.c, portio.c):
//   information header: text lines ending with an empty line, one of them FORMAT=Radiance_octree;
//   magic: 2-byte integer 283 + the size in bytes of an object index ("objsize", 4 normally);
//   bounding cube: origin x, y, z and size as %.12g text, each a NUL-terminated string;
//   scene file names as NUL-terminated strings, ended by an empty one (none if frozen);
//   number of objects: objsize-byte integer;
//   the octree: pre-order nodes, a byte each: 0 empty, 1 full (a set: objsize-byte count then that
//     many objsize-byte object indices), 2 tree (followed by its 8 children);
//   frozen octrees only, the objects: the type names as NUL-terminated strings ended by an empty
//     one, then per object: 1-byte type index (-1 ends the list), objsize-byte modifier index (-1 for
//     void), NUL-terminated identifier, 2-byte string count and strings, 2-byte real count and reals.
// Integers are big-endian two's complement. A real is a 4-byte mantissa m = frexp(x) * (2^31 - 1)
// and a 1-byte exponent e: x = (m + 0.5 - (m < 0)) / (2^31 - 1) * 2^e, or 0 if m is 0.
// Aliases are stored unresolved, as objects of type "alias": with no string, a copy of the modifier
// object; with one, a copy of the latest modifier so named, taking the alias's own modifier.
#include "scene/octree.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <optional>
#include <vector>

#include "scene/reader.h"

namespace brume {

namespace {

constexpr int kMagic = 4 * 8 + 251;  // Radiance's OCTMAGIC, to which objsize is added
constexpr int kMaxObjectSize = 8;
constexpr const char* kFormat = "Radiance_octree";
constexpr size_t kMaxHeaderBytes = 1 << 16;  // when sniffing, give up on text that is not a header

// The information header's lines, up to the empty line that ends it; nothing if the input ends first
// or has more than `limit` bytes of header. The first line must start with "#?" only when sniffing.
std::optional<std::vector<std::string>> readHeader(std::istream& in, size_t limit) {
    std::vector<std::string> lines;
    size_t bytes = 0;
    for (std::string line; std::getline(in, line);) {
        if (line.ends_with('\r')) line.pop_back();
        if (line.empty()) return lines;
        bytes += line.size() + 1;
        if (bytes > limit) return std::nullopt;
        lines.push_back(std::move(line));
    }
    return std::nullopt;
}

// The value of a "FORMAT=value" header line (spaces around it removed), or nothing.
std::optional<std::string> formatOf(const std::string& line) {
    if (!line.starts_with("FORMAT=")) return std::nullopt;
    size_t begin = line.find_first_not_of(" \t", 7), end = line.find_last_not_of(" \t");
    return begin == std::string::npos ? std::string() : line.substr(begin, end + 1 - begin);
}

// Reads the binary part of an octree, throwing "name: what" errors.
class OctreeInput {
public:
    OctreeInput(std::istream& in, std::string name) : in_(in.rdbuf()), name_(std::move(name)) {}

    [[noreturn]] void fail(const std::string& what) const { throw Error(SourceLocation{name_}, what); }

    int byte() {
        int c = in_->sbumpc();
        if (c == std::char_traits<char>::eof()) fail("truncated octree");
        return c;
    }

    // A big-endian, sign-extended integer of `size` bytes.
    long integer(int size) {
        long value = static_cast<signed char>(byte());
        for (int i = 1; i < size; ++i) value = static_cast<long>(static_cast<unsigned long>(value) << 8) | byte();
        return value;
    }

    double real() {
        long mantissa = integer(4);
        int exponent = static_cast<signed char>(byte());
        if (mantissa == 0) return 0;
        return std::ldexp((mantissa + 0.5 - (mantissa < 0)) / 2147483647.0, exponent);
    }

    std::string string() {
        std::string s;
        for (int c; (c = byte()) != 0;) s += static_cast<char>(c);
        return s;
    }

    // A count, which must not be negative.
    size_t count(int size) {
        long n = integer(size);
        if (n < 0) fail("damaged octree (negative count)");
        return static_cast<size_t>(n);
    }

    const std::string& name() const { return name_; }

private:
    std::streambuf* in_;
    std::string name_;
};

double cubeNumber(OctreeInput& input) {
    std::string s = input.string();
    double value = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(value)) input.fail("bad octree bounds");
    return value;
}

// Frozen octrees hold the tree before the objects; Brume builds its own, so this one is skipped.
// Iterative, so that a damaged file cannot exhaust the stack.
void skipTree(OctreeInput& input, int objectSize) {
    for (size_t pending = 1; pending > 0; --pending) {
        switch (input.byte()) {
            case 0: break;
            case 1:
                for (size_t n = input.count(objectSize); n > 0; --n) input.integer(objectSize);
                break;
            case 2: pending += 8; break;
            default: input.fail("damaged octree");
        }
    }
}

// One frozen alias (see the top of this file), resolved into a copy of its target.
SceneObject resolveAlias(const Scene& scene, const SceneObject& alias, OctreeInput& input) {
    int target = alias.modifier;
    if (alias.strings.size() == 1) target = scene.findModifier(alias.strings[0]);
    if (alias.strings.size() > 1 || target < 0) input.fail("bad alias '" + alias.name + "'");
    SceneObject copy = scene.objects[target];
    copy.name = alias.name;
    copy.where = alias.where;
    if (!alias.strings.empty()) copy.modifier = alias.modifier;
    return copy;
}

// Reads one frozen object into `object`; false at the end of the list.
bool readObject(OctreeInput& input, int objectSize, const std::vector<std::string>& types, int first,
                const Scene& scene, SceneObject& object) {
    int type = static_cast<signed char>(input.byte());
    if (type == -1) return false;
    if (type < 0 || static_cast<size_t>(type) >= types.size()) input.fail("reference to unknown type");
    object.type = types[type];
    long modifier = input.integer(objectSize);
    if (modifier != -1 && (modifier < 0 || modifier >= static_cast<long>(scene.objects.size()) - first))
        input.fail("bad modifier reference");  // modifiers always precede their users
    object.modifier = modifier == -1 ? -1 : static_cast<int>(first + modifier);
    object.name = input.string();
    for (size_t n = input.count(2); n > 0; --n) object.strings.push_back(input.string());
    for (size_t n = input.count(2); n > 0; --n) object.reals.push_back(input.real());
    object.where = SourceLocation{input.name()};
    return true;
}

void readFrozenObjects(Scene& scene, OctreeInput& input, int objectSize, size_t count) {
    std::vector<std::string> types;
    for (std::string type; !(type = input.string()).empty();) types.push_back(std::move(type));
    int first = static_cast<int>(scene.objects.size());
    for (SceneObject object; readObject(input, objectSize, types, first, scene, object); object = {})
        scene.add(object.type == "alias" ? resolveAlias(scene, object, input) : std::move(object));
    if (scene.objects.size() - first != count) input.fail("bad object count");
}

// A normal octree's scene files, read again as rtrace does; the object count tells if it is stale.
void readListedFiles(Scene& scene, const std::vector<std::string>& files, size_t count, const OctreeInput& input,
                     ReadOptions options) {
    options.searchRayPath = false;
    size_t first = scene.objects.size();
    try {
        for (const std::string& file : files) readSceneFile(scene, file, options);
    } catch (const Error& e) {
        input.fail(e.what());
    }
    if (scene.objects.size() - first != count) input.fail("bad object count; octree stale?");
}

}  // namespace

bool isOctree(std::istream& in) {
    std::streampos start = in.tellg();
    bool octree = false;
    if (in.get() == '#' && in.get() == '?') {
        in.seekg(start);
        if (auto lines = readHeader(in, kMaxHeaderBytes))
            for (const std::string& line : *lines) octree = octree || formatOf(line) == kFormat;
    }
    in.clear();
    in.seekg(start);
    return octree;
}

void readOctree(Scene& scene, std::istream& in, const std::string& name, const ReadOptions& options) {
    OctreeInput input(in, name);
    auto header = readHeader(in, SIZE_MAX);
    if (!header) input.fail("not an octree (no information header)");
    for (std::string& line : *header) {
        auto format = formatOf(line);
        if (!format)
            scene.headerLines.push_back(std::move(line));
        else if (*format != kFormat)
            input.fail("not an octree (FORMAT=" + *format + ")");
    }
    long objectSize = input.integer(2) - kMagic;
    if (objectSize <= 0 || objectSize > kMaxObjectSize) input.fail("incompatible octree format");
    OctreeCube cube;
    for (double& x : cube.origin) x = cubeNumber(input);
    cube.size = cubeNumber(input);
    scene.cube = cube;
    std::vector<std::string> files;
    for (std::string file; !(file = input.string()).empty();) files.push_back(std::move(file));
    size_t count = input.count(static_cast<int>(objectSize));
    scene.sources.push_back(name);
    if (!files.empty()) return readListedFiles(scene, files, count, input, options);
    skipTree(input, static_cast<int>(objectSize));
    readFrozenObjects(scene, input, static_cast<int>(objectSize), count);
}

void readOctreeFile(Scene& scene, const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(SourceLocation{path}, "cannot open octree file");
    readOctree(scene, in, path);
}

}  // namespace brume
