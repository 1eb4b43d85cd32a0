// Radiance's portable binary files (octrees, compiled meshes), the parts they share (facts from Radiance's
// portio.c, sceneio.c, header.c):
//   information header: text lines ending with an empty line, one of them FORMAT=<format>;
//   integers: big-endian two's complement of a given byte count;
//   reals: a 4-byte mantissa m = frexp(x) * (2^31 - 1) and a 1-byte exponent e:
//     x = (m + 0.5 - (m < 0)) / (2^31 - 1) * 2^e, or 0 if m is 0;
//   strings: NUL-terminated;
//   octree nodes, pre-order, a byte each: 0 empty, 1 full (an objsize-byte count then that many objsize-byte
//     indices), 2 tree (followed by its 8 children);
//   frozen objects: the type names ended by an empty one, then per object: 1-byte type index (-1 ends the
//     list), objsize-byte modifier index (-1 for void), identifier, 2-byte string count and strings,
//     2-byte real count and reals. Aliases are stored unresolved (see readFrozenObjects).
#pragma once
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace brume {

// Reads the binary part of a file, throwing "name: what" errors; `kind` names the file kind in them
// ("truncated octree").
class BinaryInput {
public:
    BinaryInput(std::istream& in, std::string name, std::string kind)
        : in_(in.rdbuf()), name_(std::move(name)), kind_(std::move(kind)) {}

    [[noreturn]] void fail(const std::string& what) const;
    int byte();
    // A big-endian, sign-extended integer of `size` bytes.
    long integer(int size);
    double real();
    std::string string();
    // A count, which must not be negative.
    size_t count(int size);
    // A number written as text (octree and mesh bounds).
    double textNumber(const std::string& what);

    const std::string& name() const { return name_; }
    const std::string& kind() const { return kind_; }

private:
    std::streambuf* in_;
    std::string name_, kind_;
};

// The information header's lines, up to the empty line that ends it; nothing if the input ends first or
// has more than `limit` bytes of header.
std::optional<std::vector<std::string>> readInfoHeader(std::istream& in, size_t limit);
// The value of a "FORMAT=value" header line (spaces around it removed), or nothing.
std::optional<std::string> formatOf(const std::string& line);

// Skips an octree's nodes (Brume builds its own acceleration structure). Iterative, so that a damaged
// file cannot exhaust the stack.
void skipOctreeNodes(BinaryInput& input, int objectSize);

// Appends frozen objects to `scene` (their modifier indices count from the first one read) and returns
// how many were read. An alias with no string is a copy of its modifier object; with one, a copy of the
// latest modifier so named, taking the alias's own modifier.
size_t readFrozenObjects(Scene& scene, BinaryInput& input, int objectSize);

}  // namespace brume
