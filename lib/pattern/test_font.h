// A font for the text tests: "I" a bar 100…150 × 20…220, "W" a block 10…240 × 20…220, a space; mean
// width 140.
#pragma once
#include "pattern/font.h"

namespace brume::test {

inline const Font& barsFont() {
    static const Font f =
        Font::parse("73 4 100 20 150 20 150 220 100 220\n87 4 10 20 240 20 240 220 10 220\n32 0\n", "t.fnt");
    return f;
}

}  // namespace brume::test
