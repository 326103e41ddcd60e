#pragma once
// Cuts progressive passes into work units small enough for one UI frame: horizontal bands of rows
// and chunks of samples. A pass of R samples per pixel is traced chunk after chunk (each chunk: r
// samples for every row, band by band), so every pixel holds the same samples when the pass ends
// and the running mean stays exact. Sizes adapt to the measured cost of each row (a row of sky
// costs a fraction of a row of ground), so that the GPU work of a frame stays near the budget
// whatever R is and wherever the band lies. Pure logic: no GL, testable.
#include <cstdint>
#include <vector>

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
    // Starts over (an image of width × height, passes of passRpp samples per pixel). The costs
    // measured so far are kept (rows mapped onto the new height): the next image is most often
    // the same scene seen a little differently.
    void restart(int width, int height, int passRpp);
    // The work per sample changed (another tracer variant or debug view, another scene): the
    // measured costs say nothing any more; units start small again, as for the first image. The
    // first unit after it (and the very first) is not measured: a new program's first draw
    // includes its JIT compile on llvmpipe (0.1-0.2 s), which says nothing about the next ones.
    void forgetCosts();
    // The next unit to trace, sized to take about budgetSeconds at the measured speed.
    WorkUnit next(double budgetSeconds);
    // What the unit returned by next() cost; feeds the speed estimate.
    void measured(const WorkUnit& unit, double seconds);
    // Mean over the rows; 0 before the first measurement.
    double secondsPerPixelSample() const;
    bool midPass() const { return row_ > 0 || chunkStart_ > 0; }

private:
    int firstRows() const;         // rows of the first unit, before anything is measured
    double rowCost(int y) const;   // seconds per pixel-sample of row y (its estimate, else the largest)
    int width_ = 1;
    int height_ = 1;
    int passRpp_ = 1;
    int chunkStart_ = 0;   // samples of the current pass done in every row
    int chunk_ = 0;        // samples of the current chunk
    int row_ = 0;          // next row of the current chunk
    std::vector<double> rowCost_;   // seconds per pixel-sample of each row; 0 = not measured yet
    double meanCost_ = 0.0;         // of the measured rows; 0 = nothing measured yet
    double maxCost_ = 0.0;          // of the measured rows
    bool unmeasuredProgram_ = true; // the next measurement is a program's first draw: skip it
};

} // namespace raylab::ui
