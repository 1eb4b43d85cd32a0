#include "util/pending_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <stdexcept>
#include <utility>

#include "util/error.h"

namespace brume {

PendingFile::PendingFile(std::string path) : path_(std::move(path)) {
    std::filesystem::path target(path_);
    std::random_device random;
    for (int attempt = 0; attempt < 100 && fd_ < 0; ++attempt) {
        char suffix[32];
        std::snprintf(suffix, sizeof suffix, ".%08x.tmp", unsigned(random()));
        name_ = (target.parent_path() / ("." + target.filename().string() + suffix)).string();
        // 0666 as for any new file: the umask decides, as it would for the path itself.
        fd_ = ::open(name_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd_ < 0 && errno != EEXIST) break;
    }
    if (fd_ < 0) throw std::runtime_error(std::strerror(errno));
}

PendingFile::~PendingFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_) ::unlink(name_.c_str());
}

void PendingFile::commit() {
    // The data reaches the disk before the name does: after a crash, the path holds the old file or the new.
    if (::fsync(fd_) != 0 || ::close(std::exchange(fd_, -1)) != 0 || std::rename(name_.c_str(), path_.c_str()) != 0)
        throw std::runtime_error(std::strerror(errno));
    committed_ = true;
}

void writeWhole(const std::string& path, const std::function<void(std::ostream&)>& write) {
    try {
        PendingFile file(path);
        {
            std::ofstream out(file.name(), std::ios::binary);
            write(out);
            if (!out.flush()) throw std::runtime_error("write failed");
        }
        file.commit();
    } catch (const std::exception& e) {
        throw Error("cannot write " + path + ": " + e.what());
    }
}

}  // namespace brume
