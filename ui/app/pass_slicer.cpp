#include "app/pass_slicer.h"

#include <algorithm>
#include <cmath>

namespace raylab::ui {

void PassSlicer::restart(int width, int height, int passRpp) {
    width_ = std::max(width, 1);
    height_ = std::max(height, 1);
    passRpp_ = std::max(passRpp, 1);
    chunkStart_ = 0;
    chunk_ = 0;
    row_ = 0;
}

WorkUnit PassSlicer::next(double budgetSeconds) {
    // Until the first measurement, start small: 1 sample over 1/8 of the rows.
    const double pixelSamples = costPerPixelSample_ > 0.0 ? budgetSeconds / costPerPixelSample_
                                                          : double(width_) * height_ / 8.0;
    if (row_ == 0) {
        // A new chunk: as many samples for the whole image as the budget allows (at least 1).
        const double fit = std::floor(pixelSamples / (double(width_) * height_));
        chunk_ = int(std::clamp(fit, 1.0, double(passRpp_ - chunkStart_)));
    }
    const double rowsFit = std::floor(pixelSamples / (double(width_) * chunk_));
    WorkUnit u;
    u.y = row_;
    u.rows = int(std::clamp(rowsFit, 1.0, double(height_ - row_)));
    u.sampleOffset = chunkStart_;
    u.rpp = chunk_;
    u.passRpp = passRpp_;
    row_ += u.rows;
    if (row_ >= height_) {
        row_ = 0;
        chunkStart_ += chunk_;
        if (chunkStart_ >= passRpp_) {
            chunkStart_ = 0;
            u.endsPass = true;
        }
    }
    return u;
}

void PassSlicer::measured(const WorkUnit& unit, double seconds) {
    const double work = double(width_) * unit.rows * unit.rpp;
    if (work <= 0.0 || seconds <= 0.0) return;
    const double c = seconds / work;
    // Smooth, but follow a slowdown at once (a heavier scene or a debug view switch).
    costPerPixelSample_ = costPerPixelSample_ > 0.0 && c < costPerPixelSample_
                              ? 0.7 * costPerPixelSample_ + 0.3 * c
                              : c;
}

} // namespace raylab::ui
