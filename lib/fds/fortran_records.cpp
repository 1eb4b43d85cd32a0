#include "fds/fortran_records.h"

#include <bit>
#include <cmath>
#include <limits>
#include <cstring>
#include <filesystem>

#include "util/error.h"

namespace brume {

static_assert(std::endian::native == std::endian::little, "FDS files are read as little endian");

FortranRecords::FortranRecords(const std::string& path) : path_(path), in_(path, std::ios::binary) {
    std::error_code ec;
    if (!in_ || std::filesystem::is_directory(path, ec)) throw Error(path + ": cannot read");
    size_ = std::filesystem::file_size(path, ec);
    if (ec) throw Error(path + ": " + ec.message());
}

FortranRecords::Next FortranRecords::next(std::vector<char>& bytes) {
    if (offset_ == size_) return Next::End;
    std::int32_t head = 0, tail = 0;
    if (size_ - offset_ < 8 || !in_.read(reinterpret_cast<char*>(&head), 4)) return Next::Truncated;
    // A record is never longer than what is left (a length read in the wrong byte order usually is).
    if (head < 0 || std::uint64_t(head) + 8 > size_ - offset_) {
        if (head >= 0 && std::uint64_t(head) < (std::uint64_t(1) << 30)) return Next::Truncated;
        throw Error(path_ + ": byte " + std::to_string(offset_) + ": not a Fortran record (length " +
                    std::to_string(head) + "; FDS's little-endian output is read)");
    }
    bytes.resize(std::size_t(head));
    if (!in_.read(bytes.data(), head) || !in_.read(reinterpret_cast<char*>(&tail), 4))
        throw Error(path_ + ": byte " + std::to_string(offset_) + ": cannot read");
    if (tail != head)
        throw Error(path_ + ": byte " + std::to_string(offset_) + ": a record's lengths differ (" +
                    std::to_string(head) + ", " + std::to_string(tail) + "): not a Fortran unformatted file");
    offset_ += std::uint64_t(head) + 8;
    return Next::Record;
}

void FortranRecords::expect(std::vector<char>& bytes, std::size_t size, const char* what) {
    std::uint64_t at = offset_;
    Next n = next(bytes);
    if (n == Next::End) throw Error(path_ + ": byte " + std::to_string(at) + ": the file ends before " + what);
    if (n == Next::Truncated)
        throw Error(path_ + ": byte " + std::to_string(at) + ": " + what + " is cut short, or this is not FDS output");
    if (bytes.size() != size)
        throw Error(path_ + ": byte " + std::to_string(at) + ": " + what + " holds " + std::to_string(bytes.size()) +
                    " bytes, not " + std::to_string(size));
}

bool forEachFrame(FortranRecords& records, const std::function<bool(std::size_t, std::uint64_t)>& readData,
                  const std::function<bool(double)>& wanted,
                  const std::function<void(std::size_t, double, std::uint64_t)>& use) {
    double previous = -std::numeric_limits<double>::infinity();  // kept or not: times increase over all frames
    std::vector<char> r;
    for (std::size_t frame = 0;; ++frame) {
        std::uint64_t at = records.offset();
        FortranRecords::Next n = records.next(r);
        if (n == FortranRecords::Next::End) return false;
        if (n == FortranRecords::Next::Truncated) return true;
        if (r.size() != 4) frameError(records, frame, at, "expected its time");
        double time = float32At(r, 0);
        if (!std::isfinite(time) || !(time > previous)) frameError(records, frame, at, "times must increase");
        at = records.offset();
        if (!readData(frame, at)) return true;
        previous = time;
        if (!wanted || wanted(time)) use(frame, time, at);
    }
}

void frameError(const FortranRecords& records, std::size_t frame, std::uint64_t byte, const std::string& what) {
    throw Error(records.path() + ": frame " + std::to_string(frame + 1) + " (byte " + std::to_string(byte) + "): " + what);
}

std::int32_t int32At(std::span<const char> bytes, std::size_t index) {
    std::int32_t v;
    std::memcpy(&v, bytes.data() + 4 * index, 4);
    return v;
}

float float32At(std::span<const char> bytes, std::size_t index) {
    float v;
    std::memcpy(&v, bytes.data() + 4 * index, 4);
    return v;
}

}  // namespace brume
