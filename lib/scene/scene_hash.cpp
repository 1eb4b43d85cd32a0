#include "scene/scene_hash.h"

#include <bit>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string_view>

#include "scene/raypath.h"

namespace brume {

namespace {

// FNV-1a with 128 bits (Fowler, Noll, Vo; draft-eastlake-fnv): a change of any one byte always changes the
// hash, and accidental collisions between scenes are out of reach; no adversary is assumed.
class Fnv128 {
public:
    void bytes(const void* data, size_t size) {
        const unsigned char* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) hash_ = (hash_ ^ p[i]) * kPrime;
    }
    // Every variable-length item is preceded by its length, so that ("ab", "c") and ("a", "bc") differ.
    void number(uint64_t n) { bytes(&n, sizeof n); }
    void real(double x) { number(std::bit_cast<uint64_t>(x)); }
    void text(std::string_view s) {
        number(s.size());
        bytes(s.data(), s.size());
    }
    std::string hex() const {
        char digits[33];
        std::snprintf(digits, sizeof digits, "%016llx%016llx", (unsigned long long)(hash_ >> 64),
                      (unsigned long long)hash_);
        return digits;
    }

private:
    static constexpr unsigned __int128 kPrime = (unsigned __int128)1 << 88 | 0x13b;
    unsigned __int128 hash_ = (unsigned __int128)0x6c62272e07bb0142 << 64 | 0x62b821756295c58d;
};

std::string fileHash(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    Fnv128 hash;
    char buffer[1 << 16];
    while (in.read(buffer, sizeof buffer) || in.gcount() > 0) hash.bytes(buffer, size_t(in.gcount()));
    if (in.bad() || !in.eof()) throw Error("cannot read " + path + " to fingerprint the scene");
    return hash.hex();
}

// The hashes of the files string arguments name, by argument; empty for arguments that name no file.
// Any string argument may be a file name (a .cal file, a data file, an octree ...): every one found along
// RAYPATH counts, even where the type would take it for something else, which at worst makes a cache
// unusable when an unrelated file of that name changes.
class FileHashes {
public:
    const std::string& of(const std::string& argument) {
        auto [it, added] = hashes_.try_emplace(argument);
        if (!added) return it->second;
        std::string path = findOnRayPath(argument);
        std::error_code error;
        if (!path.empty() && std::filesystem::is_regular_file(path, error)) it->second = fileHash(path);
        return it->second;
    }

private:
    std::map<std::string, std::string> hashes_;
};

}  // namespace

std::string sceneContentHash(const Scene& scene) {
    Fnv128 hash;
    FileHashes files;
    hash.number(scene.objects.size());
    for (const SceneObject& o : scene.objects) {
        hash.text(o.type);
        hash.text(o.name);
        hash.number(uint64_t(o.modifier));
        hash.number(o.strings.size());
        for (const std::string& s : o.strings) {
            hash.text(s);
            hash.text(files.of(s));
        }
        hash.number(o.integers.size());
        for (long n : o.integers) hash.number(uint64_t(n));
        hash.number(o.reals.size());
        for (double x : o.reals) hash.real(x);
    }
    return hash.hex();
}

}  // namespace brume
