// A file that appears whole or not at all: written under a temporary name beside its path (created
// exclusively), synced and renamed over the path by commit(); removed if never committed. Pictures, depth
// buffers and caches written this way never leave a half-written file under their name.
#pragma once
#include <functional>
#include <iosfwd>
#include <string>

namespace brume {

class PendingFile {
public:
    // Throws std::runtime_error with the system's reason when no temporary file can be made.
    explicit PendingFile(std::string path);
    PendingFile(const PendingFile&) = delete;
    PendingFile& operator=(const PendingFile&) = delete;
    ~PendingFile();

    // The temporary file's name, for writers that open files by name.
    const std::string& name() const { return name_; }
    // Renames the written file over the path; throws std::runtime_error with the system's reason.
    void commit();

private:
    std::string path_, name_;
    int fd_ = -1;
    bool committed_ = false;
};

// Writes `path` whole through a PendingFile, `write` filling the stream. Throws Error
// "cannot write path: reason".
void writeWhole(const std::string& path, const std::function<void(std::ostream&)>& write);

}  // namespace brume
