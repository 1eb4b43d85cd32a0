#include "io/ray_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <iterator>
#include <limits>
#include <sstream>

#include "scene_text.h"

using namespace brume;
using brume::test::errorOf;

namespace {

using Ray6 = std::array<double, 6>;

// Every ray of `bytes` read as `format`, or the reader's message after the rays before it.
std::string readAll(const std::string& bytes, char format, std::vector<Ray6>* rays = nullptr) {
    std::istringstream in(bytes);
    RayReader reader(in, format, "(stdin)");
    return errorOf([&] {
        for (Ray6 r; reader.next(r);)
            if (rays) rays->push_back(r);
    });
}

template <typename T>
std::string records(std::initializer_list<T> values) {
    std::string bytes(values.size() * sizeof(T), '\0');
    std::memcpy(bytes.data(), std::data(values), bytes.size());
    return bytes;
}

// A stream buffer that hands out `chunks` one underflow at a time, as a pipe delivers what was written so
// far, counting the underflows: one more than the chunks consumed means the reader waited for input it did
// not need.
class Pipe : public std::streambuf {
public:
    explicit Pipe(std::vector<std::string> chunks) : chunks_(std::move(chunks)) {}
    int underflows = 0;

protected:
    int_type underflow() override {
        if (size_t(underflows) >= chunks_.size()) return traits_type::eof();
        std::string& c = chunks_[size_t(underflows++)];
        setg(c.data(), c.data(), c.data() + c.size());
        return traits_type::to_int_type(c[0]);
    }

private:
    std::vector<std::string> chunks_;
};

}  // namespace

// C's strtod words as Radiance's isflt takes them: signs, leading and trailing points, exponents.
TEST(RayReader, ReadsTheNumbersRadianceReads) {
    std::vector<Ray6> rays;
    EXPECT_EQ(readAll("1 1. .5 1e-3 -0 +2\n\t-.25   3E+2 0 0 1e-400 -1\r\n", 'a', &rays), "no error");
    ASSERT_EQ(rays.size(), 2u);
    EXPECT_EQ(rays[0], (Ray6{1, 1, 0.5, 1e-3, 0, 2}));
    EXPECT_TRUE(std::signbit(rays[0][4]));
    EXPECT_EQ(rays[1], (Ray6{-0.25, 300, 0, 0, 0, -1}));
}

TEST(RayReader, BlankLinesAreSkippedButCounted) {
    std::vector<Ray6> rays;
    EXPECT_EQ(readAll("\n  \n0 0 1 0 0 -1\n\r\n\n0 0 2 0 0 -1", 'a', &rays), "no error");
    EXPECT_EQ(rays.size(), 2u);
    EXPECT_EQ(readAll("\n\n0 0 1 0 0 -1\n\nx\n", 'a'),
              "(stdin):5: \"x\" is not a number (a ray is six numbers: origin and direction)");
}

// Each row that is not six finite decimal numbers, and what is said about it.
TEST(RayReader, RowsThatAreNotSixNumbersNameTheirLine) {
    const std::string good = "0 0 1 0 0 -1\n";
    const std::pair<const char*, const char*> cases[] = {
        {"x y z dx dy dz", "\"x\" is not a number (a ray is six numbers: origin and direction)"},
        {"0 0 1 0 0 z", "\"z\" is not a number (a ray is six numbers: origin and direction)"},
        {"0,0,1,0,0,-1", "\"0,0,1,0,0,-1\" is not a number: fields are separated by white space, not commas"},
        {"0, 0, 1, 0, 0, -1", "\"0,\" is not a number: fields are separated by white space, not commas"},
        {"0 0 1 0 -1", "5 numbers, a ray needs 6"},
        {"7", "1 number, a ray needs 6"},
        {"0 0 1 0 0 -1 7", "7 numbers, a ray needs 6"},
        {"0 0 1 nan 0 -1", "\"nan\" is not a finite number"},
        {"0 0 1 0 0 -inf", "\"-inf\" is not a finite number"},
        {"1e999 0 1 0 0 -1", "\"1e999\" is not a finite number"},
        {"0x1p3 0 1 0 0 -1", "\"0x1p3\" is not a number (a ray is six numbers: origin and direction)"},
        {"1e 0 1 0 0 -1", "\"1e\" is not a number (a ray is six numbers: origin and direction)"},
        {". 0 1 0 0 -1", "\".\" is not a number (a ray is six numbers: origin and direction)"},
    };
    for (const auto& [row, message] : cases) {
        std::vector<Ray6> rays;
        EXPECT_EQ(readAll(good + good + row + "\n" + good, 'a', &rays), std::string("(stdin):3: ") + message) << row;
        EXPECT_EQ(rays.size(), 2u) << row;
    }
}

// A NUL byte, bytes that do not print, and words longer than any number, quoted so that they print.
TEST(RayReader, BadWordsAreQuotedPrintably) {
    EXPECT_EQ(readAll(std::string("0 0 1\0 0 0 -1\n", 14), 'a'),
              "(stdin):1: \"1\\x00\" is not a number (a ray is six numbers: origin and direction)");
    EXPECT_EQ(readAll("\x01\xff 0 0 0 0 1\n", 'a'),
              "(stdin):1: \"\\x01\\xff\" is not a number (a ray is six numbers: origin and direction)");
    EXPECT_EQ(readAll(std::string(100, '1') + " 0 0 0 0 1\n", 'a'),
              "(stdin):1: \"" + std::string(64, '1') + "...\" is too long for a number (more than 64 characters)");
}

TEST(RayReader, BinaryRecordsNameTheRayAtFault) {
    const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
    std::string two = records<float>({0, 0, 1, 0, 0, -1, 0, 0, 2, 0, 0, -1});
    std::vector<Ray6> rays;
    EXPECT_EQ(readAll(two + two.substr(0, 20), 'f', &rays), "(stdin): ray 3: partial record, 20 of 24 bytes");
    EXPECT_EQ(rays.size(), 2u);
    EXPECT_EQ(readAll(two + records<float>({0, 0, 1, nan, 0, -1}), 'f'),
              "(stdin): ray 3: number 4 of 6 is NaN, not a finite number");
    EXPECT_EQ(readAll(records<float>({0, 0, 1, 0, 0, -inf}), 'f'),
              "(stdin): ray 1: number 6 of 6 is infinite, not a finite number");
    std::string d = records<double>({0, 0, 1, 0, 0, -1});
    EXPECT_EQ(readAll(d + d.substr(0, 47), 'd'), "(stdin): ray 2: partial record, 47 of 48 bytes");
    EXPECT_EQ(readAll(d + records<double>({std::nan(""), 0, 1, 0, 0, -1}), 'd'),
              "(stdin): ray 2: number 1 of 6 is NaN, not a finite number");
}

// A program driving rtrace through a pipe writes a ray and waits for its answer: the reader must not wait
// for the line after it.
TEST(RayReader, ARayIsReadWithoutWaitingForTheNext) {
    Pipe pipe({"0 0 1 0 0 -1\n", "0 0 0 0 0 0\n"});
    std::istream in(&pipe);
    RayReader reader(in, 'a', "(stdin)");
    Ray6 r;
    ASSERT_TRUE(reader.next(r));
    EXPECT_EQ(pipe.underflows, 1);
    ASSERT_TRUE(reader.next(r));
    EXPECT_EQ(pipe.underflows, 2);
    EXPECT_FALSE(reader.next(r));
}

// The rays before a bad one make a batch of their own; the error comes with the next.
TEST(RayBatches, RaysBeforeABadOneAreBatchedThenTheErrorIsThrown) {
    std::istringstream in("0 0 1 0 0 -1\n0 0 1 0 0 -1\n0 0 0 0 0 0\n0 0 1 0 0 -1\nx\n0 0 1 0 0 -1\n");
    RayReader reader(in, 'a', "(stdin)");
    RayBatches batches(reader, 100, 0);
    std::vector<InputRay> rays;
    ASSERT_TRUE(batches.next(rays));  // ends at the flush request
    EXPECT_EQ(rays.size(), 3u);
    EXPECT_TRUE(rays.back().zero);
    ASSERT_TRUE(batches.next(rays));
    EXPECT_EQ(rays.size(), 1u);
    EXPECT_EQ(batches.first(), 3u);
    EXPECT_EQ(errorOf([&] { batches.next(rays); }),
              "(stdin):5: \"x\" is not a number (a ray is six numbers: origin and direction)");
}

// -x and -y stop reading at their count: what follows is not read, good or bad.
TEST(RayBatches, LimitStopsBeforeABadRow) {
    std::istringstream in("0 0 1 0 0 -1\n0 0 1 0 0 -1\nnot a ray\n");
    RayReader reader(in, 'a', "(stdin)");
    RayBatches batches(reader, 100, 2);
    std::vector<InputRay> rays;
    ASSERT_TRUE(batches.next(rays));
    EXPECT_EQ(rays.size(), 2u);
    EXPECT_FALSE(batches.next(rays));
}

// Directions of any finite length are made unit without overflow or underflow; only 0 0 0 asks for a flush.
TEST(InputRay, DirectionsOfAnyFiniteLengthAreMadeUnit) {
    InputRay huge = inputRay({0, 0, 1, 1e300, 0, -1e300});
    EXPECT_FALSE(huge.zero);
    EXPECT_DOUBLE_EQ(huge.dir.x, std::sqrt(0.5));
    EXPECT_DOUBLE_EQ(huge.dir.z, -std::sqrt(0.5));
    EXPECT_DOUBLE_EQ(huge.maxDistance, 1e300 * std::sqrt(2.0));
    InputRay tiny = inputRay({0, 0, 1, 4.9e-324, 0, 0});
    EXPECT_FALSE(tiny.zero);
    EXPECT_EQ(tiny.dir, dvec3(1, 0, 0));
    EXPECT_GT(tiny.maxDistance, 0);
    EXPECT_TRUE(inputRay({1, 2, 3, 0, -0.0, 0}).zero);
}
