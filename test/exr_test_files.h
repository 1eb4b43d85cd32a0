// The OpenEXR tests' pictures and files: rpict's header, a picture whose values all differ, a scratch
// directory per test and the string attributes of a file.
#pragma once
#include <gtest/gtest.h>

#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfStringAttribute.h>

#include <cmath>
#include <filesystem>
#include <iterator>
#include <string>
#include <vector>

#include "io/picture.h"

namespace brume_test {

// rpict's header, as Radiance 6.1 writes it, one hour east of Greenwich.
inline const std::vector<std::string> kRpictHeader = {
    "oconv s.rad",
    "rpict -x 8 -y 8 -vp 0 0 0 -vd 0 1 0",
    "SOFTWARE= RADIANCE 6.1a 2026-11-23 LBNL (6.1.bcffc2b52d)",
    "VIEW= -vtv -vp 0 0 0 -vd 0 1 0 -vu 0 0 1 -vh 45 -vv 45 -vo 0 -va 0 -vs 0 -vl 0",
    "PIXASPECT=1.125000",
    "CAPDATE= 2026:11:23 15:02:04",
    "GMT= 2026:11:23 14:02:04",
    "PRIMARIES= 0.6400 0.3300 0.2900 0.6000 0.1500 0.0600 0.3333 0.3333"};

// Values spanning many octaves, none repeated, so that nothing survives a mix-up of rows or channels.
inline std::vector<float> distinctValues(size_t n) {
    std::vector<float> v(n);
    for (size_t i = 0; i < n; ++i) v[i] = float(std::ldexp(1.0 + 0.001 * double(i % 997), int(i % 23) - 11));
    return v;
}

inline brume::Picture rendered(int w, int h, std::vector<std::string> header = kRpictHeader) {
    brume::Picture p;
    p.width = w;
    p.height = h;
    p.header = std::move(header);
    p.pixels = distinctValues(size_t(w) * h * 3);
    return p;
}

// A fresh directory for each test, removed with what is in it.
struct ScratchDir {
    std::filesystem::path path = std::filesystem::path(testing::TempDir()) /
                                 ("brume_exr_" + std::string(testing::UnitTest::GetInstance()->current_test_suite()->name()) +
                                  "_" + testing::UnitTest::GetInstance()->current_test_info()->name());
    ScratchDir() {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path);
    }
    ~ScratchDir() { std::filesystem::remove_all(path); }
    std::string file(const std::string& name) const { return (path / name).string(); }
    size_t entries() const {
        return size_t(std::distance(std::filesystem::directory_iterator(path), std::filesystem::directory_iterator()));
    }
};

inline const std::string& stringAttribute(const Imf::Header& h, const char* name) {
    const auto* a = h.findTypedAttribute<Imf::StringAttribute>(name);
    static const std::string missing = "(missing)";
    return a ? a->value() : missing;
}

}  // namespace brume_test
