#include "cache/cache_file.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <thread>

#include "scene_text.h"
#include "util/error.h"

namespace brume {
namespace {

namespace fs = std::filesystem;
using test::errorOf;

const CacheIdentity kIdentity{"0123456789abcdef0123456789abcdef", "-ab 2 -aa 0.1 -ad 512", 3};
constexpr size_t kHeadSize = 16;
constexpr size_t kRecordSize = 13 * 8 + 2 * 4 + 4 + 5 * 3 * 4;

// Record `id` (a distinct point per id), with numbers that survive only an exact round trip.
SurfaceRecord record(double id, int channels = 3) {
    SurfaceRecord r;
    r.point = {id, 1.0 / 3 + id, std::nextafter(id, 1e300)};
    r.normal = glm::normalize(dvec3(std::sin(id), std::cos(id), 0.7));
    r.axis = glm::normalize(glm::cross(r.normal, dvec3(0.3, -0.2, 0.9)));
    r.radius[0] = float(0.1 + id * 1e-3), r.radius[1] = 0.05f;
    r.level = int(id) % 3;
    double from = std::nextafter(60 + id, 0.0);
    r.when = RecordTime{from + 0.125, from, from + 0.25, 0.125};
    for (int i = 0; i < SurfaceRecord::kFields * channels; ++i) r.values.push_back(float(id) * 0.37f - float(i));
    return r;
}

std::vector<SurfaceRecord> records(double first, int count) {
    std::vector<SurfaceRecord> rs;
    for (int i = 0; i < count; ++i) rs.push_back(record(first + i));
    return rs;
}

bool sameBits(const dvec3& a, const dvec3& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectSame(const std::vector<SurfaceRecord>& got, const std::vector<SurfaceRecord>& expected) {
    ASSERT_EQ(got.size(), expected.size());
    for (size_t i = 0; i < got.size(); ++i) {
        const SurfaceRecord &a = got[i], &b = expected[i];
        EXPECT_TRUE(sameBits(a.point, b.point) && sameBits(a.normal, b.normal) && sameBits(a.axis, b.axis)) << i;
        EXPECT_EQ(std::memcmp(a.radius, b.radius, sizeof a.radius), 0) << i;
        EXPECT_EQ(a.level, b.level) << i;
        EXPECT_EQ(std::memcmp(&a.when, &b.when, sizeof a.when), 0) << i;
        ASSERT_EQ(a.values.size(), b.values.size()) << i;
        EXPECT_EQ(std::memcmp(a.values.data(), b.values.data(), a.values.size() * sizeof(float)), 0) << i;
    }
}

// Volume record `id` with `peaks` peaks, its numbers as record()'s.
VolumeRecord volumeRecord(double id, int peaks, int channels = 3) {
    VolumeRecord r;
    r.point = {id, 1.0 / 3 + id, std::nextafter(id, -1e300)};
    r.when = RecordTime::instant(std::nextafter(120 + id, 0.0));
    r.radius = float(0.2 + id * 1e-3);
    r.level = int(id) % 4;
    for (int i = 0; i < VolumeRecord::kFields * kShCount * channels; ++i) r.values.push_back(float(id) * 0.29f - float(i));
    for (int k = 0; k < peaks; ++k) {
        r.peakRays.push_back(glm::vec4(glm::normalize(glm::vec3(std::sin(id + k), std::cos(id + k), 0.3f)), 1 / 3.f));
        for (int c = 0; c < channels; ++c) r.peakFlux.push_back(float(id + k) / 7 + float(c));
    }
    r.sourcePeaks = peaks / 2;
    return r;
}

void expectSame(const std::vector<VolumeRecord>& got, const std::vector<VolumeRecord>& expected) {
    ASSERT_EQ(got.size(), expected.size());
    auto bits = [](const auto& v) { return std::string(reinterpret_cast<const char*>(v.data()), v.size() * sizeof v[0]); };
    for (size_t i = 0; i < got.size(); ++i) {
        const VolumeRecord &a = got[i], &b = expected[i];
        EXPECT_TRUE(sameBits(a.point, b.point)) << i;
        EXPECT_EQ(std::memcmp(&a.when, &b.when, sizeof a.when), 0) << i;
        EXPECT_EQ(std::memcmp(&a.radius, &b.radius, sizeof a.radius), 0) << i;
        EXPECT_EQ(a.level, b.level) << i;
        EXPECT_EQ(a.sourcePeaks, b.sourcePeaks) << i;
        EXPECT_EQ(bits(a.values), bits(b.values)) << i;
        EXPECT_EQ(bits(a.peakRays), bits(b.peakRays)) << i;
        EXPECT_EQ(bits(a.peakFlux), bits(b.peakFlux)) << i;
    }
}

std::string contents(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void overwrite(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

// Each test its own file, removed afterwards.
class CacheFileTest : public testing::Test {
protected:
    CacheFileTest()
        : path_((fs::temp_directory_path() / ("brume_cache_" + std::to_string(getpid()) + "_" +
                                              testing::UnitTest::GetInstance()->current_test_info()->name()))
                    .string()) {
        fs::remove(path_);
    }
    ~CacheFileTest() override { fs::remove(path_); }

    // The file holding blocks of `sizes` records (ids from 0 on); returns where each block starts.
    std::vector<size_t> writeBlocks(const std::vector<int>& sizes) {
        CacheFile file(path_, kIdentity);
        std::vector<size_t> starts;
        double id = 0;
        for (int n : sizes) {
            starts.push_back(fs::file_size(path_));
            file.append(records(id, n));
            id += n;
        }
        return starts;
    }

    std::string path_;
};

TEST_F(CacheFileTest, RecordsComeBackBitExact) {
    std::vector<SurfaceRecord> written = records(0.1, 7);
    CacheFile(path_, kIdentity).append(written);
    expectSame(CacheFile(path_, kIdentity).readNew(), written);

    std::string single = path_ + ".mono";
    CacheFile(single, {"s", "o", 1}).append({record(2.5, 1)});
    expectSame(CacheFile(single, {"s", "o", 1}).readNew(), {record(2.5, 1)});
    fs::remove(single);
}

// Volume records (blocks of their own, their sizes varying with their peaks) come back bit-exact, in their
// order, beside surface records.
TEST_F(CacheFileTest, VolumeRecordsComeBackBitExactBesideSurfaceRecords) {
    std::vector<VolumeRecord> first{volumeRecord(0.5, 0), volumeRecord(1.5, 3)}, second{volumeRecord(2.5, 32)};
    {
        CacheFile file(path_, kIdentity);
        file.append(records(0, 2));
        file.append(first);
        file.append(records(2, 1));
        file.append(second);
    }
    CacheFile file(path_, kIdentity);
    expectSame(file.readNewVolumes(), {first[0], first[1], second[0]});
    expectSame(file.readNew(), records(0, 3));
}

// A volume record whose peaks would reach past its block, or with a direction that is no unit vector, is a
// damaged file (checksums matching: a faulty writer), reported at the record; such records are never written.
TEST_F(CacheFileTest, AVolumeRecordThatDoesNotFitOrIsInvalidIsCorruption) {
    writeBlocks({1});
    size_t volumes = fs::file_size(path_);
    CacheFile(path_, kIdentity).append(std::vector<VolumeRecord>{volumeRecord(0, 2)});
    const std::string whole = contents(path_);
    auto plant = [&](size_t at, const void* value, size_t size) {
        std::string bytes = whole;
        std::memcpy(bytes.data() + at, value, size);
        char* head = bytes.data() + volumes;
        auto crc = [](const char* data, size_t n) { return uint32_t(crc32(0, (const Bytef*)data, uInt(n))); };
        uint32_t recordsCrc = crc(head + kHeadSize, bytes.size() - volumes - kHeadSize), headCrc;
        std::memcpy(head + 8, &recordsCrc, 4);
        headCrc = crc(head, 12);
        std::memcpy(head + 12, &headCrc, 4);
        overwrite(path_, bytes);
        return errorOf([&] { CacheFile(path_, kIdentity).readNewVolumes(); });
    };
    const size_t record = volumes + kHeadSize, peaksAt = record + 7 * 8 + 4 + 4;
    int32_t tooMany = 3;
    std::string e = plant(peaksAt, &tooMany, 4);
    EXPECT_EQ(e.find(path_ + ": byte " + std::to_string(record) + ": damaged cache block (a volume record does not fit"), 0u)
        << e;
    float longer = 2;
    e = plant(peaksAt + 8 + VolumeRecord::kFields * kShCount * 3 * 4, &longer, 4);
    EXPECT_NE(e.find("invalid volume record: a peak's direction or distance is invalid"), std::string::npos) << e;
    int32_t moreSources = 3;
    e = plant(peaksAt + 4, &moreSources, 4);
    EXPECT_NE(e.find("invalid volume record: its sources' peaks are not among its peaks"), std::string::npos) << e;

    CacheFile file(path_, kIdentity);
    VolumeRecord nan = volumeRecord(1, 1), skewed = volumeRecord(2, 1), mono = volumeRecord(3, 1, 1);
    nan.peakFlux[1] = std::nanf("");
    skewed.peakRays[0].x += 0.5f;
    for (const VolumeRecord& r : {nan, skewed, mono})
        EXPECT_THROW(file.append(std::vector<VolumeRecord>{volumeRecord(0, 0), r}), std::invalid_argument);
}

TEST_F(CacheFileTest, NewFileStartsWithItsHeader) {
    overwrite(path_, "");  // an empty file is taken as a new one
    CacheFile file(path_, kIdentity);
    EXPECT_EQ(contents(path_), "#?BRUME_IRRADIANCE_CACHE\nFORMAT=brume_irradiance_cache 4\n"
                               "SCENE=0123456789abcdef0123456789abcdef\nOPTIONS=-ab 2 -aa 0.1 -ad 512\nCHANNELS=3\n\n");
    EXPECT_TRUE(file.readNew().empty());
    EXPECT_EQ(file.path(), path_);
}

TEST_F(CacheFileTest, ReadNewReturnsOnlyWhatOthersAppendedSinceTheLastCall) {
    CacheFile a(path_, kIdentity);
    a.append(records(0, 3));
    CacheFile b(path_, kIdentity);
    expectSame(b.readNew(), records(0, 3));
    EXPECT_TRUE(a.readNew().empty()) << "a's own records";
    EXPECT_TRUE(b.readNew().empty()) << "already returned";

    b.append(records(10, 2));
    a.append(records(20, 1));  // a reads b's block before appending its own, and keeps it for readNew
    b.append(records(30, 1));
    expectSame(a.readNew(), {record(10), record(11), record(30)});
    expectSame(b.readNew(), {record(20)});
}

TEST_F(CacheFileTest, RefusesAFileMadeForAnotherSceneOptionsOrChannels) {
    CacheFile(path_, kIdentity).append(records(0, 1));
    std::string scene = errorOf([&] { CacheFile(path_, {"feedbeef", kIdentity.options, 3}); });
    EXPECT_NE(scene.find("made for another scene"), std::string::npos) << scene;
    std::string options = errorOf([&] { CacheFile(path_, {kIdentity.scene, "-ab 3 -aa 0.1 -ad 512", 3}); });
    EXPECT_NE(options.find("other options: -ab 2 (now -ab 3)"),
              std::string::npos)
        << options;
    std::string channels = errorOf([&] { CacheFile(path_, {kIdentity.scene, kIdentity.options, 81}); });
    EXPECT_NE(channels.find("values of 3 channels, not 81"), std::string::npos) << channels;
    for (const std::string& e : {scene, options, channels}) {
        EXPECT_NE(e.find(path_), std::string::npos) << e;
        EXPECT_NE(e.find("remove it or use another -af file"), std::string::npos) << e;
    }
    // A refused file is left as it was.
    expectSame(CacheFile(path_, kIdentity).readNew(), records(0, 1));
}

// Files of formats 1 (Brume before records kept their instant), 2 (before volume records held the sources'
// light) and 3 (before records served windows of time) are refused, and left as they were.
TEST_F(CacheFileTest, RefusesFilesOfEarlierFormats) {
    const std::pair<int, std::string> formats[] = {
        {1, "whose records have no instant"},
        {2, "whose volume records hold no light straight from the sources"},
        {3, "whose records hold one instant, not a window of them"}};
    for (const auto& [format, why] : formats) {
        std::string old = "#?BRUME_IRRADIANCE_CACHE\nFORMAT=brume_irradiance_cache " + std::to_string(format) +
                          "\nSCENE=" + kIdentity.scene + "\nOPTIONS=" + kIdentity.options + "\nCHANNELS=3\n\n";
        overwrite(path_, old);
        std::string e = errorOf([&] { CacheFile(path_, kIdentity); });
        EXPECT_EQ(e, "cache file " + path_ + " was made by an earlier Brume (cache format " + std::to_string(format) +
                         ", " + why + "); remove it or use another -af file");
        EXPECT_EQ(contents(path_), old);
    }
}

// A damaged header's bytes are shown as printable text in the refusal (never binary on a terminal): \xNN, at
// most 80 bytes.
TEST_F(CacheFileTest, RefusalsShowAHeadersBytesAsPrintableText) {
    overwrite(path_, "#?BRUME_IRRADIANCE_CACHE\nFORMAT=br\x01\xff\x1b[2J" + std::string(100, 'x') + "\n\n");
    std::string e = errorOf([&] { CacheFile(path_, kIdentity); });
    EXPECT_NE(e.find("(FORMAT=br\\x01\\xff\\x1b[2J" + std::string(72, 'x') + "...)"), std::string::npos) << e;
}

TEST_F(CacheFileTest, RefusesAFileThatIsNotACache) {
    overwrite(path_, "void plastic red 0 0 5 1 0 0 0 0\n");
    EXPECT_EQ(errorOf([&] { CacheFile(path_, kIdentity); }),
              path_ + ": byte 0: not a Brume irradiance cache file; remove it or use another -af file");
}

TEST_F(CacheFileTest, ABlockCutShortIsDroppedAndTheFileRepaired) {
    std::vector<size_t> starts = writeBlocks({2, 3});
    std::string whole = contents(path_);
    // Cut inside the last block's records, then inside its head.
    for (size_t cut : {whole.size() - 10, starts[1] + 7}) {
        overwrite(path_, whole.substr(0, cut));
        CacheFile file(path_, kIdentity);
        testing::internal::CaptureStderr();
        expectSame(file.readNew(), records(0, 2));
        std::string warning = testing::internal::GetCapturedStderr();
        EXPECT_NE(warning.find("dropping the incomplete block at byte " + std::to_string(starts[1])),
                  std::string::npos)
            << warning;
        EXPECT_EQ(fs::file_size(path_), starts[1]);
        file.append(records(7, 1));
        expectSame(CacheFile(path_, kIdentity).readNew(), {record(0), record(1), record(7)});
    }
}

TEST_F(CacheFileTest, AFlippedByteIsReportedWithItsBlocksOffset) {
    std::vector<size_t> starts = writeBlocks({2, 3, 1});
    std::string whole = contents(path_);
    // In the second block's records, then in its head (its count).
    for (size_t at : {starts[1] + kHeadSize + kRecordSize + 5, starts[1] + 4}) {
        std::string damaged = whole;
        damaged[at] ^= 0x10;
        overwrite(path_, damaged);
        std::string e = errorOf([&] { CacheFile(path_, kIdentity).readNew(); });
        EXPECT_EQ(e.find(path_ + ": byte " + std::to_string(starts[1]) + ": "), 0u) << e;
        EXPECT_NE(e.find("damaged"), std::string::npos) << e;
    }
}

// Replaces the first record of the file's first block by `r`, with checksums that match: a record no
// checksum catches, written by a faulty writer.
void plantRecord(const std::string& path, size_t blockStart, const SurfaceRecord& r) {
    std::string bytes = contents(path);
    char* p = bytes.data() + blockStart + kHeadSize;
    std::memcpy(p, &r.point, 24);
    std::memcpy(p + 24, &r.normal, 24);
    std::memcpy(p + 48, &r.axis, 24);
    std::memcpy(p + 72, &r.when.at, 8);
    std::memcpy(p + 80, &r.when.from, 8);
    std::memcpy(p + 88, &r.when.to, 8);
    std::memcpy(p + 96, &r.when.spacing, 8);
    std::memcpy(p + 104, r.radius, 8);
    uint32_t count;
    std::memcpy(&count, bytes.data() + blockStart + 4, 4);
    auto crc = [](const char* data, size_t size) { return uint32_t(crc32(0, (const Bytef*)data, uInt(size))); };
    uint32_t recordsCrc = crc(p, count * kRecordSize), headCrc;
    std::memcpy(bytes.data() + blockStart + 8, &recordsCrc, 4);
    headCrc = crc(bytes.data() + blockStart, 12);
    std::memcpy(bytes.data() + blockStart + 12, &headCrc, 4);
    overwrite(path, bytes);
}

TEST_F(CacheFileTest, AnInvalidRecordInTheFileIsCorruptionNotAValue) {
    size_t start = writeBlocks({2})[0];
    SurfaceRecord bad = record(0);
    bad.normal *= 2;
    plantRecord(path_, start, bad);
    std::string e = errorOf([&] { CacheFile(path_, kIdentity).readNew(); });
    std::string where = path_ + ": byte " + std::to_string(start + kHeadSize) + ": ";
    EXPECT_EQ(e.find(where + "damaged cache block (invalid record: its normal or axis is not a unit vector)"), 0u) << e;

    bad = record(0);
    bad.radius[1] = std::nanf("");
    plantRecord(path_, start, bad);
    e = errorOf([&] { CacheFile(path_, kIdentity).readNew(); });
    EXPECT_NE(e.find("invalid record: a radius is not positive"), std::string::npos) << e;

    // A window that does not hold the record's instant, or whose records are not spaced within it.
    for (RecordTime when : {RecordTime{5, 6, 8, 1}, RecordTime{7, 6, 8, 0}, RecordTime{6, 6, 6, 1},
                            RecordTime{0, -INFINITY, INFINITY, 2}}) {
        bad = record(0);
        bad.when = when;
        plantRecord(path_, start, bad);
        e = errorOf([&] { CacheFile(path_, kIdentity).readNew(); });
        EXPECT_NE(e.find("invalid record: its window of time is invalid"), std::string::npos) << e;
    }
}

TEST_F(CacheFileTest, InvalidRecordsAreNeverWritten) {
    CacheFile file(path_, kIdentity);
    SurfaceRecord nan = record(1), flat = record(2), mono = record(3, 1);
    nan.values[4] = std::nanf("");
    flat.radius[0] = 0;
    for (const SurfaceRecord& r : {nan, flat, mono})
        EXPECT_THROW(file.append({record(0), r}), std::invalid_argument);
    EXPECT_TRUE(CacheFile(path_, kIdentity).readNew().empty());
}

// Every record of ids [0, writers × blocks × kPerBlock) read from the file exactly once.
constexpr int kPerBlock = 3;

void expectEveryRecordOnce(const std::string& path, int writers, int blocks) {
    std::map<double, int> seen;
    for (const SurfaceRecord& r : CacheFile(path, kIdentity).readNew()) ++seen[r.point.x];
    ASSERT_EQ(seen.size(), size_t(writers * blocks * kPerBlock));
    for (auto [id, times] : seen) {
        EXPECT_EQ(times, 1) << id;
        EXPECT_TRUE(id == std::floor(id) && id >= 0 && id < writers * blocks * kPerBlock) << id;
    }
}

void appendBlocks(CacheFile& file, int writer, int blocks) {
    for (int b = 0; b < blocks; ++b) file.append(records((writer * blocks + b) * kPerBlock, kPerBlock));
}

TEST_F(CacheFileTest, ProcessesWritingAtOnceLoseAndInterleaveNothing) {
    constexpr int kWriters = 2, kBlocks = 200;
    std::vector<pid_t> children;
    for (int w = 0; w < kWriters; ++w) {
        pid_t pid = fork();
        ASSERT_GE(pid, 0);
        if (pid == 0) {
            // Both children create the file if neither finds it: one writes the header, the other reads it.
            try {
                CacheFile file(path_, kIdentity);
                appendBlocks(file, w, kBlocks);
                _exit(0);
            } catch (...) {
                _exit(2);
            }
        }
        children.push_back(pid);
    }
    for (pid_t pid : children) {
        int status = 0;
        ASSERT_EQ(waitpid(pid, &status, 0), pid);
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
    }
    expectEveryRecordOnce(path_, kWriters, kBlocks);
}

TEST_F(CacheFileTest, ThreadsSharingOneFileLoseAndInterleaveNothing) {
    constexpr int kThreads = 4, kBlocks = 100;
    CacheFile file(path_, kIdentity);
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) threads.emplace_back([&, t] { appendBlocks(file, t, kBlocks); });
    for (std::thread& t : threads) t.join();
    EXPECT_TRUE(file.readNew().empty()) << "all its own";
    expectEveryRecordOnce(path_, kThreads, kBlocks);
}

TEST_F(CacheFileTest, ThreadsWithAFileObjectEachLoseAndInterleaveNothing) {
    constexpr int kThreads = 4, kBlocks = 100;
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t)
        threads.emplace_back([&, t] {
            CacheFile file(path_, kIdentity);
            appendBlocks(file, t, kBlocks);
        });
    for (std::thread& t : threads) t.join();
    expectEveryRecordOnce(path_, kThreads, kBlocks);
}

// Random damage to a valid file: every outcome is records that are valid, or an Error; never a crash,
// another exception or a NaN.
TEST_F(CacheFileTest, DamagedFilesLoadOrFailCleanly) {
    writeBlocks({2, 1, 4});
    CacheFile(path_, kIdentity).append(std::vector<VolumeRecord>{volumeRecord(0, 1), volumeRecord(1, 4)});
    const std::string whole = contents(path_);
    std::mt19937 random(7);
    auto below = [&](size_t n) { return size_t(random() % n); };
    setWarningsEnabled(false);
    int loaded = 0, refused = 0;
    for (int trial = 0; trial < 400; ++trial) {
        std::string damaged = whole;
        switch (trial % 3) {
        case 0: damaged.resize(below(whole.size())); break;
        case 1:
            for (int i = 0, n = 1 + int(below(8)); i < n; ++i) damaged[below(damaged.size())] = char(random());
            break;
        case 2: {
            size_t at = below(damaged.size()), n = below(200);
            damaged.resize(std::max(damaged.size(), at + n));
            for (size_t i = at; i < at + n; ++i) damaged[i] = char(random());
        }
        }
        overwrite(path_, damaged);
        try {
            CacheFile file(path_, kIdentity);
            for (const SurfaceRecord& r : file.readNew())
                ASSERT_TRUE(std::isfinite(r.point.x) && r.radius[0] > 0 && r.values.size() == 15u);
            for (const VolumeRecord& r : file.readNewVolumes())
                ASSERT_TRUE(std::isfinite(r.point.x) && r.radius > 0 && r.peakFlux.size() == 3u * r.peaks());
            file.append(records(100, 1));
            CacheFile(path_, kIdentity).readNew();
            ++loaded;
        } catch (const Error&) {
            ++refused;
        }
    }
    setWarningsEnabled(true);
    EXPECT_GT(loaded, 0);
    EXPECT_GT(refused, 0);
}

}  // namespace
}  // namespace brume
