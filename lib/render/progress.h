// Progress of a long computation on stderr: Radiance's report lines every -t seconds ("rpict: 5120 samples,
// 42.00% after 0.010 hours"), or, when nothing was asked and stderr is a terminal, one line kept up to date.
// Called from many threads; reports are written by whichever thread finds one due.
#pragma once
#include <atomic>
#include <chrono>
#include <mutex>
#include <string>

namespace brume {

class ProgressMeter {
public:
    // interval > 0: a report line every `interval` seconds; 0: the live line on a terminal, else nothing.
    ProgressMeter(std::string program, double interval);
    ~ProgressMeter();

    // Starts a new job of `total` units (a frame's pixels).
    void start(long total);
    // `units` more done, `samples` more samples traced for them.
    void advance(long units, long samples);
    // The job is done: the last report (100%) and, for the live line, its end.
    void finish();

private:
    void report(bool last);
    using Clock = std::chrono::steady_clock;
    std::string program_;
    double interval_;
    bool live_;
    std::atomic<long> done_{0}, samples_{0};
    long total_ = 0;
    Clock::time_point begin_, next_;
    std::mutex mutex_;
};

}  // namespace brume
