#include "cache/cache_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <algorithm>
#include <bit>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>

#include "util/error.h"

namespace brume {

// Records are copied to and from the file as they are in memory.
static_assert(std::endian::native == std::endian::little && std::numeric_limits<double>::is_iec559,
              "cache files hold little-endian IEEE 754 numbers");

namespace {

constexpr std::string_view kMagic = "#?BRUME_IRRADIANCE_CACHE";
constexpr std::string_view kFormat = "brume_irradiance_cache 4";
constexpr char kSurfaceTag[4] = {'S', 'U', 'R', 'F'};  // a block of surface records
constexpr char kVolumeTag[4] = {'V', 'O', 'L', 'U'};   // a block of volume records
// A volume record holds at most this many peaks (buildVolumeRecord keeps 32, and up to 36 per source); more
// is a damaged file.
constexpr int32_t kMaxPeaks = 1 << 16;
constexpr size_t kHeadSize = 16;
// A header is a few hundred bytes; one without its empty line within this many is not a cache file's.
constexpr size_t kMaxHeaderSize = 1 << 16;

// Open file description locks (Linux) rather than F_SETLKW's per-process ones: two CacheFile objects of one
// process on the same file then exclude each other, and closing one does not drop the other's lock.
#ifdef F_OFD_SETLKW
constexpr int kLockWait = F_OFD_SETLKW;
#else
constexpr int kLockWait = F_SETLKW;
#endif

std::string systemReason() { return std::strerror(errno); }

// An exclusive lock on the whole file, for as long as the object lives.
class FileLock {
public:
    FileLock(int fd, const std::string& path) : fd_(fd) {
        if (!set(F_WRLCK)) throw Error("cannot lock cache file " + path + ": " + systemReason());
    }
    FileLock(const FileLock&) = delete;
    FileLock& operator=(const FileLock&) = delete;
    ~FileLock() { set(F_UNLCK); }

private:
    bool set(short type) {
        struct flock lock {};
        lock.l_type = type;
        lock.l_whence = SEEK_SET;
        int status;
        while ((status = fcntl(fd_, kLockWait, &lock)) != 0 && errno == EINTR) {}
        return status == 0;
    }
    int fd_;
};

uint64_t fileSize(int fd, const std::string& path) {
    struct stat s;
    if (fstat(fd, &s) != 0) throw Error("cannot read cache file " + path + ": " + systemReason());
    return uint64_t(s.st_size);
}

// Reads up to `size` bytes at `offset`; fewer only at the end of the file.
size_t readAt(int fd, const std::string& path, void* data, size_t size, uint64_t offset) {
    size_t done = 0;
    while (done < size) {
        ssize_t n = pread(fd, static_cast<char*>(data) + done, size - done, off_t(offset + done));
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) throw Error("cannot read cache file " + path + ": " + systemReason());
        if (n == 0) break;
        done += size_t(n);
    }
    return done;
}

// Writes `bytes` at `offset` and syncs them. On failure cuts the file back to `offset`, so that no partial
// block remains (were that to fail too, the next reader drops it as torn), and throws Error.
void writeAt(int fd, const std::string& path, std::string_view bytes, uint64_t offset) {
    std::string reason;
    for (size_t done = 0; done < bytes.size() && reason.empty();) {
        ssize_t n = pwrite(fd, bytes.data() + done, bytes.size() - done, off_t(offset + done));
        if (n > 0)
            done += size_t(n);
        else if (n == 0 || errno != EINTR)
            reason = n == 0 ? "no space written" : systemReason();
    }
    if (reason.empty() && fsync(fd) == 0) return;
    if (reason.empty()) reason = systemReason();
    [[maybe_unused]] int ignored = ftruncate(fd, off_t(offset));
    throw Error("cannot write cache file " + path + ": " + reason);
}

std::string headerText(const CacheIdentity& id) {
    if (id.scene.find('\n') != std::string::npos || id.options.find('\n') != std::string::npos || id.channels < 1)
        throw std::invalid_argument("cache identity with a newline or no channels");
    return std::string(kMagic) + "\nFORMAT=" + std::string(kFormat) + "\nSCENE=" + id.scene +
           "\nOPTIONS=" + id.options + "\nCHANNELS=" + std::to_string(id.channels) + "\n\n";
}

[[noreturn]] void corrupted(const std::string& path, uint64_t offset, const std::string& why) {
    throw Error(path + ": byte " + std::to_string(offset) + ": " + why + "; remove it or use another -af file");
}

bool finite(const dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool unit(const dvec3& v) { return std::abs(glm::length(v) - 1) < 1e-6; }

// Why a record's time may not be cached: a window of time that holds its instant, with its records' spacing
// (every instant: infinite window and spacing; one instant: no window, no spacing).
const char* invalidity(const RecordTime& t) {
    if (!std::isfinite(t.at)) return "its instant is not finite";
    if (t.from == t.to ? t.from != t.at || t.spacing != 0
                       : !(t.from <= t.at && t.at <= t.to) || !(t.spacing > 0) ||
                             (std::isinf(t.spacing) != (std::isinf(t.from) && std::isinf(t.to))))
        return "its window of time is invalid";
    return nullptr;
}

// Why a record may not be cached (its numbers would reach the renderer), or null.
const char* invalidity(const SurfaceRecord& r, int channels) {
    if (r.values.size() != size_t(SurfaceRecord::kFields) * channels) return "wrong number of values";
    if (!finite(r.point) || !finite(r.normal) || !finite(r.axis)) return "a coordinate is not finite";
    if (const char* why = invalidity(r.when)) return why;
    if (!unit(r.normal) || !unit(r.axis)) return "its normal or axis is not a unit vector";
    for (float radius : r.radius)
        if (!(radius > 0) || !std::isfinite(radius)) return "a radius is not positive";
    if (r.level < 0) return "its level is negative";
    for (float v : r.values)
        if (!std::isfinite(v)) return "a value is not finite";
    return nullptr;
}

const char* invalidity(const VolumeRecord& r, int channels) {
    if (r.values.size() != size_t(VolumeRecord::kFields) * kShCount * channels) return "wrong number of values";
    if (r.peakFlux.size() != r.peakRays.size() * channels) return "wrong number of peak values";
    if (r.peaks() > kMaxPeaks) return "too many peaks";
    if (r.sourcePeaks < 0 || r.sourcePeaks > r.peaks()) return "its sources' peaks are not among its peaks";
    if (!finite(r.point)) return "a coordinate is not finite";
    if (const char* why = invalidity(r.when)) return why;
    if (!(r.radius > 0) || !std::isfinite(r.radius)) return "its radius is not positive";
    if (r.level < 0) return "its level is negative";
    for (float v : r.values)
        if (!std::isfinite(v)) return "a value is not finite";
    for (const glm::vec4& ray : r.peakRays)
        if (!(std::abs(glm::length(glm::vec3(ray)) - 1) < 1e-4f) || !(ray.w >= 0) || !std::isfinite(ray.w))
            return "a peak's direction or distance is invalid";
    for (float v : r.peakFlux)
        if (!std::isfinite(v)) return "a peak's value is not finite";
    return nullptr;
}

template <class T>
void put(char*& p, T value) {
    std::memcpy(p, &value, sizeof value);
    p += sizeof value;
}

template <class T>
T get(const char*& p) {
    T value;
    std::memcpy(&value, p, sizeof value);
    p += sizeof value;
    return value;
}

void putTime(char*& p, const RecordTime& t) {
    for (double v : {t.at, t.from, t.to, t.spacing}) put(p, v);
}

RecordTime getTime(const char*& p) {
    RecordTime t;
    for (double* v : {&t.at, &t.from, &t.to, &t.spacing}) *v = get<double>(p);
    return t;
}

void putRecord(char*& p, const SurfaceRecord& r) {
    for (const dvec3* v : {&r.point, &r.normal, &r.axis})
        for (int i = 0; i < 3; ++i) put(p, (*v)[i]);
    putTime(p, r.when);
    put(p, r.radius[0]);
    put(p, r.radius[1]);
    put(p, int32_t(r.level));
    for (float v : r.values) put(p, v);
}

SurfaceRecord getRecord(const char*& p, int channels) {
    SurfaceRecord r;
    for (dvec3* v : {&r.point, &r.normal, &r.axis})
        for (int i = 0; i < 3; ++i) (*v)[i] = get<double>(p);
    r.when = getTime(p);
    r.radius[0] = get<float>(p);
    r.radius[1] = get<float>(p);
    r.level = get<int32_t>(p);
    r.values.resize(size_t(SurfaceRecord::kFields) * channels);
    for (float& v : r.values) v = get<float>(p);
    return r;
}

// A volume record's point, time, radius, level, number of peaks and of the sources' among them; then its
// values.
constexpr size_t kVolumeRecordHead = 7 * sizeof(double) + sizeof(float) + 3 * sizeof(int32_t);

size_t volumeRecordSize(int peaks, int channels) {
    return kVolumeRecordHead +
           (size_t(VolumeRecord::kFields) * kShCount * channels + size_t(peaks) * (4 + channels)) * sizeof(float);
}

void putRecord(char*& p, const VolumeRecord& r) {
    for (int i = 0; i < 3; ++i) put(p, r.point[i]);
    putTime(p, r.when);
    put(p, r.radius);
    put(p, int32_t(r.level));
    put(p, int32_t(r.peaks()));
    put(p, int32_t(r.sourcePeaks));
    for (float v : r.values) put(p, v);
    for (const glm::vec4& ray : r.peakRays)
        for (int i = 0; i < 4; ++i) put(p, ray[i]);
    for (float v : r.peakFlux) put(p, v);
}

// The volume record at p, if the `end` of its block leaves room for it (else nothing: a damaged block).
std::optional<VolumeRecord> getVolumeRecord(const char*& p, const char* end, int channels) {
    if (size_t(end - p) < kVolumeRecordHead) return std::nullopt;
    VolumeRecord r;
    for (int i = 0; i < 3; ++i) r.point[i] = get<double>(p);
    r.when = getTime(p);
    r.radius = get<float>(p);
    r.level = get<int32_t>(p);
    int32_t peaks = get<int32_t>(p);
    r.sourcePeaks = get<int32_t>(p);
    if (peaks < 0 || peaks > kMaxPeaks || size_t(end - p) < volumeRecordSize(peaks, channels) - kVolumeRecordHead)
        return std::nullopt;
    r.values.resize(size_t(VolumeRecord::kFields) * kShCount * channels);
    for (float& v : r.values) v = get<float>(p);
    r.peakRays.resize(size_t(peaks));
    for (glm::vec4& ray : r.peakRays)
        for (int i = 0; i < 4; ++i) ray[i] = get<float>(p);
    r.peakFlux.resize(size_t(peaks) * channels);
    for (float& v : r.peakFlux) v = get<float>(p);
    return r;
}

uint32_t crc(const char* data, size_t size) {
    return uint32_t(crc32_z(crc32_z(0, nullptr, 0), reinterpret_cast<const Bytef*>(data), size));
}

// The block head: its tag, the record count (surface records) or the records' size in bytes (volume records,
// whose size varies with their peaks), the records' CRC and the CRC of these first 12 bytes.
struct BlockHead {
    bool volumes = false;
    uint32_t size = 0, recordsCrc = 0;
};

void putHead(char* p, const BlockHead& head) {
    char* start = p;
    std::memcpy(p, head.volumes ? kVolumeTag : kSurfaceTag, 4);
    p += 4;
    put(p, head.size);
    put(p, head.recordsCrc);
    put(p, crc(start, 12));
}

// The head at `p`, or nothing if it is not one (a damaged file).
std::optional<BlockHead> getHead(const char* p) {
    const char* start = p;
    BlockHead head;
    head.volumes = std::memcmp(p, kVolumeTag, 4) == 0;
    if (!head.volumes && std::memcmp(p, kSurfaceTag, 4) != 0) return std::nullopt;
    p += 4;
    head.size = get<uint32_t>(p);
    head.recordsCrc = get<uint32_t>(p);
    if (get<uint32_t>(p) != crc(start, 12)) return std::nullopt;
    return head;
}

}  // namespace

CacheFile::CacheFile(std::string path, CacheIdentity identity)
    : path_(std::move(path)), identity_(std::move(identity)),
      recordSize_(13 * sizeof(double) + 2 * sizeof(float) + sizeof(int32_t) +
                  size_t(SurfaceRecord::kFields) * identity_.channels * sizeof(float)) {
    std::string header = headerText(identity_);
    fd_ = open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd_ < 0) throw Error("cannot open cache file " + path_ + ": " + systemReason());
    try {
        // Under the lock, so that of two processes creating the file one writes the header and the
        // other finds it whole.
        FileLock lock(fd_, path_);
        if (fileSize(fd_, path_) == 0) {
            writeAt(fd_, path_, header, 0);
            offset_ = header.size();
        } else {
            checkHeader();
        }
    } catch (...) {
        close(fd_);
        throw;
    }
}

CacheFile::~CacheFile() { close(fd_); }

// Header text from the file as a message may show it (a damaged file must not write binary to a terminal).
static std::string shown(std::string_view text) { return shownBytes(text, 80); }

// The options of an OPTIONS= text, each with its values ("-ab 5", "-av 0 0 0"), and the program's version.
static std::vector<std::string> optionGroups(std::string_view text) {
    std::vector<std::string> groups;
    std::istringstream words{std::string(text)};
    for (std::string w; words >> w;) {
        bool starts = groups.empty() || (w.size() > 1 && w[0] == '-' && std::isalpha(static_cast<unsigned char>(w[1])));
        if (starts) groups.push_back(w);
        else groups.back() += " " + w;
    }
    return groups;
}

// "-ab 5 (now -ab 4)": what differs between the file's options and the run's.
static std::string optionDifference(std::string_view file, std::string_view now) {
    std::vector<std::string> a = optionGroups(file), b = optionGroups(now), onlyA, onlyB;
    for (const std::string& g : a)
        if (std::find(b.begin(), b.end(), g) == b.end()) onlyA.push_back(g);
    for (const std::string& g : b)
        if (std::find(a.begin(), a.end(), g) == a.end()) onlyB.push_back(g);
    auto join = [](const std::vector<std::string>& v) {
        std::string out;
        for (const std::string& g : v) out += (out.empty() ? "" : " ") + g;
        return out.empty() ? std::string("none") : out;
    };
    return shown(join(onlyA)) + " (now " + join(onlyB) + ")";
}

void CacheFile::checkHeader() {
    std::string text(kMaxHeaderSize, '\0');
    text.resize(readAt(fd_, path_, text.data(), text.size(), 0));
    size_t end = text.find("\n\n");
    if (!text.starts_with(std::string(kMagic) + "\n") || end == std::string::npos)
        corrupted(path_, 0, "not a Brume irradiance cache file");
    std::map<std::string, std::string, std::less<>> fields;
    for (size_t line = kMagic.size() + 1; line <= end; line = text.find('\n', line) + 1) {
        std::string_view l(text.data() + line, text.find('\n', line) - line);
        if (size_t equals = l.find('='); equals != l.npos)
            fields[std::string(l.substr(0, equals))] = l.substr(equals + 1);
    }
    auto refuse = [&](const std::string& what) {
        throw Error("cache file " + path_ + " " + what + "; remove it or use another -af file");
    };
    if (fields["FORMAT"] == "brume_irradiance_cache 1")
        refuse("was made by an earlier Brume (cache format 1, whose records have no instant)");
    if (fields["FORMAT"] == "brume_irradiance_cache 2")
        refuse("was made by an earlier Brume (cache format 2, whose volume records hold no light straight from the "
               "sources)");
    if (fields["FORMAT"] == "brume_irradiance_cache 3")
        refuse("was made by an earlier Brume (cache format 3, whose records hold one instant, not a window of them)");
    if (fields["FORMAT"] != kFormat) refuse("has another format (FORMAT=" + shown(fields["FORMAT"]) + ")");
    if (fields["SCENE"] != identity_.scene)
        refuse("was made for another scene (its SCENE= differs: the scene or a file it reads has changed)");
    if (fields["OPTIONS"] != identity_.options)
        refuse("was made with other options: " + optionDifference(fields["OPTIONS"], identity_.options));
    if (fields["CHANNELS"] != std::to_string(identity_.channels))
        refuse("holds values of " + shown(fields["CHANNELS"]) + " channels, not " + std::to_string(identity_.channels));
    offset_ = end + 2;
}

void CacheFile::catchUp() {
    uint64_t size = fileSize(fd_, path_);
    while (offset_ < size) {
        char headBytes[kHeadSize];
        size_t got = readAt(fd_, path_, headBytes, kHeadSize, offset_);
        std::optional<BlockHead> head = got == kHeadSize ? getHead(headBytes) : std::nullopt;
        if (got == kHeadSize && !head) corrupted(path_, offset_, "damaged cache block (no block head)");
        uint64_t recordsSize = !head ? 0 : head->volumes ? head->size : uint64_t(head->size) * recordSize_;
        if (!head || recordsSize > size - offset_ - kHeadSize) {
            // A writer died mid-append: writers hold the lock we hold until their block is whole.
            warn(path_ + ": dropping the incomplete block at byte " + std::to_string(offset_) +
                 " (a process stopped while writing it)");
            if (ftruncate(fd_, off_t(offset_)) != 0 || fsync(fd_) != 0)
                throw Error("cannot repair cache file " + path_ + ": " + systemReason());
            return;
        }
        std::string records(recordsSize, '\0');
        readAt(fd_, path_, records.data(), records.size(), offset_ + kHeadSize);
        if (crc(records.data(), records.size()) != head->recordsCrc)
            corrupted(path_, offset_, "damaged cache block (its checksum does not match its records)");
        if (head->volumes) readVolumes(records);
        else readSurfaces(records, head->size);
        offset_ += kHeadSize + recordsSize;
    }
}

void CacheFile::readSurfaces(const std::string& records, uint32_t count) {
    std::vector<SurfaceRecord> block;
    const char* p = records.data();
    for (uint32_t i = 0; i < count; ++i) {
        block.push_back(getRecord(p, identity_.channels));
        if (const char* why = invalidity(block.back(), identity_.channels))
            corrupted(path_, offset_ + kHeadSize + i * recordSize_,
                      std::string("damaged cache block (invalid record: ") + why + ")");
    }
    unread_.insert(unread_.end(), block.begin(), block.end());
}

void CacheFile::readVolumes(const std::string& records) {
    std::vector<VolumeRecord> block;
    const char *p = records.data(), *end = p + records.size();
    while (p < end) {
        uint64_t at = offset_ + kHeadSize + uint64_t(p - records.data());
        std::optional<VolumeRecord> r = getVolumeRecord(p, end, identity_.channels);
        if (!r) corrupted(path_, at, "damaged cache block (a volume record does not fit in it)");
        if (const char* why = invalidity(*r, identity_.channels))
            corrupted(path_, at, std::string("damaged cache block (invalid volume record: ") + why + ")");
        block.push_back(std::move(*r));
    }
    unreadVolumes_.insert(unreadVolumes_.end(), std::make_move_iterator(block.begin()),
                          std::make_move_iterator(block.end()));
}

std::vector<SurfaceRecord> CacheFile::readNew() {
    std::lock_guard guard(mutex_);
    FileLock lock(fd_, path_);
    catchUp();
    return std::exchange(unread_, {});
}

std::vector<VolumeRecord> CacheFile::readNewVolumes() {
    std::lock_guard guard(mutex_);
    FileLock lock(fd_, path_);
    catchUp();
    return std::exchange(unreadVolumes_, {});
}

void CacheFile::append(const std::vector<SurfaceRecord>& records) {
    if (records.empty()) return;
    std::string block(kHeadSize + records.size() * recordSize_, '\0');
    char* p = block.data() + kHeadSize;
    for (const SurfaceRecord& r : records) {
        if (const char* why = invalidity(r, identity_.channels))
            throw std::invalid_argument(std::string("cannot cache an invalid irradiance record: ") + why);
        putRecord(p, r);
    }
    putHead(block.data(), {false, uint32_t(records.size()), crc(block.data() + kHeadSize, block.size() - kHeadSize)});
    appendBlock(block);
}

void CacheFile::append(const std::vector<VolumeRecord>& records) {
    if (records.empty()) return;
    size_t bytes = 0;
    for (const VolumeRecord& r : records) {
        if (const char* why = invalidity(r, identity_.channels))
            throw std::invalid_argument(std::string("cannot cache an invalid volume record: ") + why);
        bytes += volumeRecordSize(r.peaks(), identity_.channels);
    }
    if (bytes > std::numeric_limits<uint32_t>::max()) {  // a block's size is 32 bits: split in two
        size_t half = records.size() / 2;
        append(std::vector<VolumeRecord>(records.begin(), records.begin() + half));
        append(std::vector<VolumeRecord>(records.begin() + half, records.end()));
        return;
    }
    std::string block(kHeadSize + bytes, '\0');
    char* p = block.data() + kHeadSize;
    for (const VolumeRecord& r : records) putRecord(p, r);
    putHead(block.data(), {true, uint32_t(bytes), crc(block.data() + kHeadSize, bytes)});
    appendBlock(block);
}

void CacheFile::appendBlock(const std::string& block) {
    std::lock_guard guard(mutex_);
    FileLock lock(fd_, path_);
    // What others appended is read first: the file then ends at offset_, past any torn block.
    catchUp();
    writeAt(fd_, path_, block, offset_);
    offset_ += block.size();
}

}  // namespace brume
