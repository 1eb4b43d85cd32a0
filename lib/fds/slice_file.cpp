#include "fds/slice_file.h"

#include <cmath>

#include "fds/fortran_records.h"
#include "util/error.h"

namespace brume {

namespace {

constexpr size_t kLabel = 30;  // FDS's labels are 30 characters, padded with blanks

std::string label(const std::vector<char>& r) {
    std::string s(r.begin(), r.end());
    size_t end = s.find_last_not_of(' ');
    return end == std::string::npos ? std::string() : s.substr(0, end + 1);
}

}  // namespace

SliceFile readSlice(const std::string& path, const std::function<bool(double)>& wanted) {
    FortranRecords records(path);
    SliceFile file;
    std::vector<char> r;
    records.expect(r, kLabel, "the quantity");
    file.quantity = label(r);
    records.expect(r, kLabel, "the short label");
    records.expect(r, kLabel, "the units");
    file.units = label(r);
    records.expect(r, 24, "the index range");
    size_t values = 1;
    for (int i = 0; i < 6; ++i) file.range[i] = int32At(r, size_t(i));
    for (int axis = 0; axis < 3; ++axis) {
        int lo = file.range[2 * axis], hi = file.range[2 * axis + 1];
        if (lo < 0 || hi < lo || hi - lo > 100000) throw Error(path + ": bad index range in its header");
        values *= size_t(hi - lo + 1);
    }
    if (values > (size_t(1) << 31)) throw Error(path + ": bad index range in its header");
    file.truncated = forEachFrame(
        records,
        [&](size_t k, std::uint64_t at) {
            if (records.next(r) != FortranRecords::Next::Record) return false;
            if (r.size() != 4 * values)
                frameError(records, k, at, "holds " + std::to_string(r.size() / 4) + " values, not " + std::to_string(values));
            return true;
        },
        wanted,
        [&](size_t k, double time, std::uint64_t at) {
            SliceFrame& frame = file.frames.emplace_back(SliceFrame{time, std::vector<float>(values)});
            for (size_t i = 0; i < values; ++i) {
                frame.values[i] = float32At(r, i);
                if (!std::isfinite(frame.values[i])) frameError(records, k, at, "a value is not a number (an unstable run?)");
            }
        });
    return file;
}

}  // namespace brume
