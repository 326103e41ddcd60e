#pragma once
// Splits a UI frame's time between tracing and everything else: the tracing budget of the next
// frame is the target frame time minus what the rest of a frame (display pass, ImGui, drawing,
// swap) has been costing, so frames stay near the target whatever the rpp or window size. Tracing
// gets at least a share in proportion to the rest, so a loaded machine or a large window makes
// frames slower instead of starving the image.
#include <algorithm>

namespace raylab::ui {

class FramePacer {
public:
    // Tracing gets at least this fraction of what the rest of the frame costs (a quarter of the
    // frame), up to the target.
    static constexpr double kMinShareOfRest = 1.0 / 3.0;

    explicit FramePacer(double targetSeconds, double minTraceSeconds = 0.002)
        : target_(targetSeconds), minTrace_(minTraceSeconds) {}
    // The last frame took frameSeconds, of which traceSeconds tracing.
    void frameDone(double frameSeconds, double traceSeconds) {
        const double other = std::max(0.0, frameSeconds - traceSeconds);
        other_ = other_ < 0.0 ? other : 0.8 * other_ + 0.2 * other;   // smoothed: frames jitter
    }
    double traceBudget() const {
        const double other = std::max(other_, 0.0);
        const double floor = std::max(minTrace_, kMinShareOfRest * other);
        return std::clamp(target_ - other, std::min(floor, std::max(target_, minTrace_)), std::max(target_, minTrace_));
    }
    double otherSeconds() const { return std::max(other_, 0.0); }

private:
    double target_;
    double minTrace_;
    double other_ = -1.0;   // not measured yet
};

} // namespace raylab::ui
