// The records of a Fortran sequential unformatted file, as FDS writes its binary output (gfortran, little
// endian): each record is a 4-byte length, that many bytes, and the length again.
#pragma once
#include <cstdint>
#include <fstream>
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

// FDS writes an output frame as a record of its time and records of its data. The time of frame `frame` (from
// 0), after `previous` (−∞ for the first): Record with `time` set, or End, or Truncated, as next() says.
// Throws frameError where the record is not a time after `previous`.
FortranRecords::Next nextFrameTime(FortranRecords& records, std::size_t frame, double previous, double& time);
// Error "path: frame N (byte B): what", N counted from 1.
[[noreturn]] void frameError(const FortranRecords& records, std::size_t frame, std::uint64_t byte,
                             const std::string& what);

// Little-endian values out of a record.
std::int32_t int32At(std::span<const char> bytes, std::size_t index);
float float32At(std::span<const char> bytes, std::size_t index);

}  // namespace brume
