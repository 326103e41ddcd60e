#include "app/pass_slicer.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace raylab::ui {
namespace {

// A unit that took this many times its prediction changes the estimate of every row.
constexpr double kSurprise = 1.5;

} // namespace

void PassSlicer::restart(int width, int height, int passRpp) {
    width_ = std::max(width, 1);
    passRpp_ = std::max(passRpp, 1);
    if (std::max(height, 1) != height_ || rowCost_.empty()) {
        const int newHeight = std::max(height, 1);
        std::vector<double> costs(std::size_t(newHeight), 0.0);
        if (!rowCost_.empty())
            for (int y = 0; y < newHeight; ++y)
                costs[std::size_t(y)] = rowCost_[std::size_t(std::int64_t(y) * height_ / newHeight)];
        rowCost_ = std::move(costs);
        height_ = newHeight;
    }
    chunkStart_ = 0;
    chunk_ = 0;
    row_ = 0;
}

double PassSlicer::rowCost(int y) const {
    // A row not measured yet costs what the costliest measured one does: better a unit too small
    // than a frame too long.
    const double c = rowCost_[std::size_t(y)];
    return c > 0.0 ? c : maxCost_;
}

void PassSlicer::forgetCosts() {
    std::fill(rowCost_.begin(), rowCost_.end(), 0.0);
    meanCost_ = 0.0;
    maxCost_ = 0.0;
    unmeasuredProgram_ = true;
}

int PassSlicer::firstRows() const { return std::max(height_ / 8, 1); }

double PassSlicer::secondsPerPixelSample() const { return meanCost_; }

WorkUnit PassSlicer::next(double budgetSeconds) {
    WorkUnit u;
    u.y = row_;
    u.sampleOffset = chunkStart_;
    u.passRpp = passRpp_;
    if (meanCost_ <= 0.0) {
        // Until the first measurement, start small: 1 sample over 1/8 of the rows.
        if (row_ == 0) chunk_ = 1;
        u.rows = std::min(firstRows(), height_ - row_);
    } else {
        if (row_ == 0) {
            // A new chunk: as many samples for the whole image as the budget allows (at least 1).
            double image = 0.0;   // seconds per sample of every pixel
            for (int y = 0; y < height_; ++y) image += rowCost(y) * width_;
            chunk_ = int(std::clamp(std::floor(budgetSeconds / image), 1.0, double(passRpp_ - chunkStart_)));
        }
        // As many rows from row_ on as fit, by what each of them costs (at least one); of rows
        // never measured, no more than the first unit took: their cost is a guess.
        double seconds = 0.0;
        int unknown = 0;
        u.rows = 0;
        while (row_ + u.rows < height_) {
            const int y = row_ + u.rows;
            const double row = rowCost(y) * width_ * chunk_;
            if (u.rows > 0 && (seconds + row > budgetSeconds || (rowCost_[std::size_t(y)] <= 0.0 && unknown >= firstRows())))
                break;
            seconds += row;
            unknown += rowCost_[std::size_t(y)] <= 0.0;
            ++u.rows;
        }
    }
    u.rpp = chunk_;
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
    if (unit.rows <= 0 || unit.rpp <= 0 || seconds <= 0.0) return;
    if (std::exchange(unmeasuredProgram_, false)) return;
    const double samples = double(width_) * unit.rpp;
    const int end = std::min(unit.y + unit.rows, height_);
    // The time splits over the unit's rows as their estimates did (evenly when none had one),
    // scaled to what was measured: the profile within a band is kept, its level corrected.
    double predicted = 0.0;
    for (int y = unit.y; y < end; ++y) predicted += rowCost(y) * samples;
    const double ratio = predicted > 0.0 ? seconds / predicted : 1.0;
    if (predicted <= 0.0) {
        for (int y = unit.y; y < end; ++y) rowCost_[std::size_t(y)] = seconds / (double(end - unit.y) * samples);
    } else if (ratio > kSurprise) {
        // Far slower than its rows promised (the camera turned from the sky to the ground, more
        // bounces): every row is that much dearer. Better small units for a while than one long
        // frame for each band not traced since.
        const double unmeasured = maxCost_ * ratio;
        for (double& c : rowCost_) c *= ratio;
        for (int y = unit.y; y < end; ++y)
            if (rowCost_[std::size_t(y)] <= 0.0) rowCost_[std::size_t(y)] = unmeasured;
    } else {
        // Smooth (units jitter), but follow a slowdown at once.
        const double r = ratio < 1.0 ? 0.7 + 0.3 * ratio : ratio;
        for (int y = unit.y; y < end; ++y) rowCost_[std::size_t(y)] = rowCost(y) * r;
    }
    double sum = 0.0;
    int known = 0;
    maxCost_ = 0.0;
    for (double c : rowCost_)
        if (c > 0.0) sum += c, ++known, maxCost_ = std::max(maxCost_, c);
    meanCost_ = known > 0 ? sum / known : 0.0;
}

} // namespace raylab::ui
