// The records of a Fortran sequential unformatted file, as FDS writes its binary output (gfortran, little
// endian): each record is a 4-byte length, that many bytes, and the length again.
#pragma once
#include <cstdint>
#include <fstream>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace brume {

class FortranRecords {
public:
    // Opens `path`; throws Error "path: what" if it cannot be read.
    explicit FortranRecords(const std::string& path);

    enum class Next { Record, End, Truncated };
    // The next record's bytes into `bytes`: Record; End where the file ends between records; Truncated where
    // it ends inside one (a run still writing, or killed). Throws Error "path: byte N: what" where the two
    // lengths of a record differ (not an FDS file, or a big-endian one, which is not read).
    Next next(std::vector<char>& bytes);
    // The next record, which must be there and hold `size` bytes; `what` names it in the error otherwise.
    void expect(std::vector<char>& bytes, std::size_t size, const char* what);

    // Byte offset of the next record, for messages.
    std::uint64_t offset() const { return offset_; }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    std::ifstream in_;
    std::uint64_t offset_ = 0;
    std::uint64_t size_ = 0;
};

// FDS writes an output frame as a record of its time and records of its data. For each frame: its time (which
// must increase: frameError otherwise), then `readData(frame, at)` reads its data records (frame from 0, `at` the
// byte offset of its first, for messages), returning false where the file ends inside them; `use(frame, time,
// at)` then takes each whole frame `wanted` keeps (all where it is null). Returns whether the file ended inside a
// frame (a run still writing, or killed): that frame is dropped.
bool forEachFrame(FortranRecords& records, const std::function<bool(std::size_t, std::uint64_t)>& readData,
                  const std::function<bool(double)>& wanted,
                  const std::function<void(std::size_t, double, std::uint64_t)>& use);
// Error "path: frame N (byte B): what", N counted from 1.
[[noreturn]] void frameError(const FortranRecords& records, std::size_t frame, std::uint64_t byte,
                             const std::string& what);

// Little-endian values out of a record.
std::int32_t int32At(std::span<const char> bytes, std::size_t index);
float float32At(std::span<const char> bytes, std::size_t index);

}  // namespace brume
