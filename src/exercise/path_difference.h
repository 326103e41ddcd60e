#pragma once
// Where a pupil's paths first part from the reference's: the same samples of one pixel recorded by
// the path inspector with each function, compared term by term in the order the tracer computes
// them, so the first term that differs names the stage the pupil's function feeds.
#include "inspect/path_record.h"

#include <string>
#include <vector>

namespace raylab::exercise {

struct PathDifference {
    bool found = false;
    int path = -1;          // index into the recorded paths
    std::uint64_t sample = 0;
    int bounce = -1;        // -1: the paths agree term by term and differ in value only, or not at all
    std::string term;       // the term, in a pupil's words, e.g. "the camera ray's hit distance"
    std::string mine;       // its value with the pupil's function
    std::string reference;  // its value with the reference
};

// Relative tolerance of the comparison: float rounding of a correct function written another
// way stays far below it.
constexpr double kPathTolerance = 1e-3;

// The first term (path by path, bounce by bounce) where `mine` and `reference` differ; both must
// be recordings of the same samples of the same pixel.
PathDifference firstPathDifference(const std::vector<PathRecord>& mine, const std::vector<PathRecord>& reference);

// One sentence for the check's message, e.g. "sample 3, bounce 0: the camera ray's hit distance
// is 4.1 with your function and 4.5 with the reference".
std::string describe(const PathDifference& d);

} // namespace raylab::exercise
