#pragma once
// χ² cells for samples of the unit disk (the thin lens): an n × n grid over the disk's bounding
// square; the expected count of a cell is N × its area inside the disk / π (the uniform pdf 1/π
// integrated on 64 × 64 sub-cells). Cells wholly outside have expected 0: a sample there fails
// the χ² test outright (sampleInZeroCell).
#include "support/statistics.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace raylab::test {

class DiskHistogram {
public:
    explicit DiskHistogram(int n = 21) : n_(n), observed_(std::size_t(n * n), 0.0) {}

    void add(float x, float y) {   // x, y in [-1, 1]
        const int cx = std::clamp(int((x + 1.0f) * 0.5f * float(n_)), 0, n_ - 1);
        const int cy = std::clamp(int((y + 1.0f) * 0.5f * float(n_)), 0, n_ - 1);
        observed_[std::size_t(cy * n_ + cx)] += 1.0;
        ++count_;
    }

    ChiSquareResult chiSquare() const {
        constexpr int sub = 64;
        std::vector<double> expected(observed_.size(), 0.0);
        for (int cy = 0; cy < n_; ++cy)
            for (int cx = 0; cx < n_; ++cx) {
                int inside = 0;
                for (int sy = 0; sy < sub; ++sy)
                    for (int sx = 0; sx < sub; ++sx) {
                        const double x = -1.0 + 2.0 * (cx + (sx + 0.5) / sub) / n_;
                        const double y = -1.0 + 2.0 * (cy + (sy + 0.5) / sub) / n_;
                        inside += x * x + y * y <= 1.0;
                    }
                const double cellArea = (2.0 / n_) * (2.0 / n_) * inside / double(sub * sub);
                expected[std::size_t(cy * n_ + cx)] = double(count_) * cellArea / M_PI;
            }
        return chiSquareTest(observed_, expected);
    }

private:
    int n_;
    std::vector<double> observed_;
    long count_ = 0;
};

} // namespace raylab::test
