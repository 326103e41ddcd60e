#pragma once
// --report-frames: the UI frame times and their parts, printed at exit.
#include <string>
#include <vector>

namespace raylab::ui {

struct FrameTimes {
    std::vector<double> ms, traceMs, displayMs, drawMs, swapMs;
    std::vector<double> residentMiB;   // with --frame-log only
    void report() const;
    // --frame-log: "ms resident_MiB" per frame.
    void write(const std::string& path) const;
};

// The process's resident set (/proc/self/statm), MiB.
double residentMiB();

} // namespace raylab::ui
