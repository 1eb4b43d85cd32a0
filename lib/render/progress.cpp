#include "render/progress.h"

#include <unistd.h>

#include <cstdio>

namespace brume {

namespace {

constexpr double kLiveInterval = 0.5;  // seconds between updates of the live line

}  // namespace

ProgressMeter::ProgressMeter(std::string program, double interval)
    : program_(std::move(program)), interval_(interval), live_(interval <= 0 && ::isatty(STDERR_FILENO)) {}

ProgressMeter::~ProgressMeter() {
    if (live_ && total_ > 0 && done_ < total_) std::fputc('\n', stderr);  // leave the shell prompt clean
}

void ProgressMeter::start(long total) {
    std::lock_guard lock(mutex_);
    done_ = 0, samples_ = 0, total_ = total;
    begin_ = Clock::now();
    next_ = begin_ + std::chrono::duration_cast<Clock::duration>(
                         std::chrono::duration<double>(live_ ? kLiveInterval : interval_));
}

void ProgressMeter::advance(long units, long samples) {
    done_ += units, samples_ += samples;
    if ((!live_ && interval_ <= 0) || Clock::now() < next_) return;
    std::unique_lock lock(mutex_, std::try_to_lock);
    if (!lock || Clock::now() < next_) return;  // another thread is reporting, or just did
    report(false);
    next_ = Clock::now() + std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>(live_ ? kLiveInterval : interval_));
}

void ProgressMeter::finish() {
    std::lock_guard lock(mutex_);
    if (live_ || interval_ > 0) report(true);
    total_ = 0;
}

void ProgressMeter::report(bool last) {
    double hours = std::chrono::duration<double>(Clock::now() - begin_).count() / 3600;
    double percent = total_ > 0 ? 100.0 * double(done_) / double(total_) : 100;
    if (live_)
        std::fprintf(stderr, "\r%s: %5.1f%% after %.0f s (%ld samples)%s", program_.c_str(), percent, hours * 3600,
                     long(samples_), last ? "\n" : "");
    else
        std::fprintf(stderr, "%s: %ld samples, %4.2f%% after %.3f hours\n", program_.c_str(), long(samples_),
                     percent, hours);
    std::fflush(stderr);
}

}  // namespace brume
