// FDS's slice files (.sf, SLCF/SLCC in the .smv): a quantity's float values over an index range of a mesh at
// each output instant. Over a volume (a 3D slice) it is the whole field; cell-centred (SLCC) slices are the
// cells' own values, the best source of a density FDS computed.
#pragma once
#include <array>
#include <functional>
#include <string>
#include <vector>

namespace brume {

struct SliceFrame {
    double time;                // seconds
    std::vector<float> values;  // over the range, i fastest, then j, then k
};

struct SliceFile {
    std::string quantity, units;  // as in the file's own labels
    std::array<int, 6> range{};   // i1 i2 j1 j2 k1 k2
    std::vector<SliceFrame> frames;
    bool truncated = false;       // the file ended inside a frame (dropped)
};

// The frames of `path` at times `wanted` says (all by default). Throws Error "path: …" where it is not a slice file, a frame holds the wrong number
// of values or a non-finite one, or times do not increase.
SliceFile readSlice(const std::string& path, const std::function<bool(double)>& wanted = nullptr);

}  // namespace brume
