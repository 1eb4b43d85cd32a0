// The octree format, as Radiance's oconv writes it (facts from its writeoct.c; the shared parts of Radiance's
// binary files are described in binary_input.h):
//   information header with FORMAT=Radiance_octree;
//   magic: 2-byte integer 283 + the size in bytes of an object index ("objsize", 4 normally);
//   bounding cube: origin x, y, z and size as %.12g text, each a NUL-terminated string;
//   scene file names as NUL-terminated strings, ended by an empty one (none if frozen);
//   number of objects: objsize-byte integer;
//   the octree's nodes;
//   frozen octrees only, the objects.
#include "scene/octree.h"

#include <cstdint>
#include <fstream>
#include <vector>

#include "scene/binary_input.h"
#include "scene/reader.h"

namespace brume {

namespace {

constexpr int kMagic = 4 * 8 + 251;  // Radiance's OCTMAGIC, to which objsize is added
constexpr int kMaxObjectSize = 8;
constexpr const char* kFormat = "Radiance_octree";
constexpr size_t kMaxHeaderBytes = 1 << 16;  // when sniffing, give up on text that is not a header

// A normal octree's scene files, read again as rtrace does; the object count tells if it is stale.
void readListedFiles(Scene& scene, const std::vector<std::string>& files, size_t count, const BinaryInput& input,
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
        if (auto lines = readInfoHeader(in, kMaxHeaderBytes))
            for (const std::string& line : *lines) octree = octree || formatOf(line) == kFormat;
    }
    in.clear();
    in.seekg(start);
    return octree;
}

void readOctree(Scene& scene, std::istream& in, const std::string& name, const ReadOptions& options,
                std::vector<std::string>* listed) {
    BinaryInput input(in, name, "octree");
    auto header = readInfoHeader(in, SIZE_MAX);
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
    for (double& x : cube.origin) x = input.textNumber("bounds");
    cube.size = input.textNumber("bounds");
    scene.cube = cube;
    std::vector<std::string> files;
    for (std::string file; !(file = input.string()).empty();) files.push_back(std::move(file));
    size_t count = input.count(static_cast<int>(objectSize));
    scene.sources.push_back(name);
    if (listed) *listed = files;
    if (!files.empty()) return readListedFiles(scene, files, count, input, options);
    skipOctreeNodes(input, static_cast<int>(objectSize));
    if (readFrozenObjects(scene, input, static_cast<int>(objectSize)) != count) input.fail("bad object count");
}

void readOctreeFile(Scene& scene, const std::string& path, std::vector<std::string>* listed) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(SourceLocation{path}, "cannot open octree file");
    readOctree(scene, in, path, {}, listed);
}

}  // namespace brume
