#pragma once
// Cuts progressive passes into work units small enough for one UI frame: horizontal bands of rows
// and chunks of samples. A pass of R samples per pixel is traced chunk after chunk (each chunk: r
// samples for every row, band by band), so every pixel holds the same samples when the pass ends
// and the running mean stays exact. Sizes adapt to the measured cost per pixel-sample so that the
// GPU work of a frame stays near the budget whatever R is. Pure logic: no GL, testable.
#include <cstdint>

namespace raylab::ui {

struct WorkUnit {
    int y = 0;              // first row (GL order, bottom row 0)
    int rows = 0;
    int sampleOffset = 0;   // samples of this pass already in these rows
    int rpp = 0;            // samples to add now
    bool endsPass = false;  // the last unit of its pass: call finishPass(passRpp) after it
    int passRpp = 0;
};

class PassSlicer {
public:
    // Starts over (an image of width × height, passes of passRpp samples per pixel).
    void restart(int width, int height, int passRpp);
    // The next unit to trace, sized to take about budgetSeconds at the measured speed.
    WorkUnit next(double budgetSeconds);
    // What the unit returned by next() cost; feeds the speed estimate.
    void measured(const WorkUnit& unit, double seconds);
    double secondsPerPixelSample() const { return costPerPixelSample_; }
    bool midPass() const { return row_ > 0 || chunkStart_ > 0; }

private:
    int width_ = 1;
    int height_ = 1;
    int passRpp_ = 1;
    int chunkStart_ = 0;   // samples of the current pass done in every row
    int chunk_ = 0;        // samples of the current chunk
    int row_ = 0;          // next row of the current chunk
    double costPerPixelSample_ = 0.0;   // seconds; 0 = not measured yet
};

} // namespace raylab::ui
