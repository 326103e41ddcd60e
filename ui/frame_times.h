#pragma once
// --report-frames: the UI frame times and their parts, printed at exit.
#include <vector>

namespace raylab::ui {

struct FrameTimes {
    std::vector<double> ms, traceMs, displayMs, drawMs, swapMs;
    void report() const;
};

} // namespace raylab::ui
