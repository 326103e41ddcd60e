#include "frame_times.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <numeric>

namespace raylab::ui {
namespace {

double mean(const std::vector<double>& v) {
    return v.empty() ? 0.0 : std::accumulate(v.begin(), v.end(), 0.0) / double(v.size());
}

} // namespace

void FrameTimes::report() const {
    if (ms.empty()) return;
    std::vector<double> s = ms;
    std::sort(s.begin(), s.end());
    const double m = mean(s);
    const auto over50 = s.end() - std::upper_bound(s.begin(), s.end(), 50.0);
    std::printf("frames %zu: mean %.2f ms (%.1f fps), median %.2f ms, p95 %.2f ms, max %.2f ms, %td over 50 ms\n", s.size(),
                m, 1000.0 / m, s[s.size() / 2], s[std::min(s.size() - 1, s.size() * 95 / 100)], s.back(), over50);
    double slowestTrace = 0.0;
    for (double t : traceMs) slowestTrace = std::max(slowestTrace, t);
    std::printf("slowest tracing in one frame: %.2f ms\n", slowestTrace);
    std::printf("per frame (means): trace %.2f ms, display pass %.2f ms, UI draw %.2f ms, swap %.2f ms, other %.2f ms\n",
                mean(traceMs), mean(displayMs), mean(drawMs), mean(swapMs),
                m - mean(traceMs) - mean(displayMs) - mean(drawMs) - mean(swapMs));
}

double residentMiB() {
    std::ifstream statm("/proc/self/statm");
    double pages = 0.0, resident = 0.0;
    statm >> pages >> resident;
    return resident * double(::sysconf(_SC_PAGESIZE)) / 1048576.0;
}

void FrameTimes::write(const std::string& path) const {
    std::FILE* f = std::fopen(path.c_str(), "w");
    if (!f) {
        std::fprintf(stderr, "raylab: cannot write %s\n", path.c_str());
        return;
    }
    for (std::size_t i = 0; i < ms.size(); ++i)
        std::fprintf(f, "%.3f %.3f\n", ms[i], i < residentMiB.size() ? residentMiB[i] : 0.0);
    std::fclose(f);
}

} // namespace raylab::ui
