// For the FDS readers' tests: Fortran records written as FDS writes them, and the shared FDS case.
#pragma once
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace brume::fds_test {

// One record: its length, its bytes, its length again (little endian, as on the machines FDS runs on).
inline void writeRecord(std::ofstream& out, const void* bytes, std::int32_t size) {
    out.write(reinterpret_cast<const char*>(&size), 4);
    out.write(static_cast<const char*>(bytes), size);
    out.write(reinterpret_cast<const char*>(&size), 4);
}

template <typename T>
void writeRecord(std::ofstream& out, const std::vector<T>& values) {
    writeRecord(out, values.data(), std::int32_t(values.size() * sizeof(T)));
}

// ../shared/data/fds/fdsvismap_room_fire (FDS 6.7.9 output), or "" when the shared data is absent.
inline std::string sharedCase() {
    std::filesystem::path dir = std::filesystem::path(BRUME_SHARED_DATA) / "fds" / "fdsvismap_room_fire";
    return std::filesystem::exists(dir / "model.smv") ? dir.string() : std::string();
}

// test/data/fds/two_mesh_smoke: a small FDS 6.9.0 case of two meshes (its README says how it was made).
inline std::string twoMeshCase() { return std::string(BRUME_TEST_DATA) + "/fds/two_mesh_smoke"; }

}  // namespace brume::fds_test
