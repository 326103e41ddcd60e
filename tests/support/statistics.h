#pragma once
// The statistics the tests use live in src/stats (the viewer's self-test uses them too).
#include "stats/chi_square.h"
#include "stats/sample_statistics.h"

namespace raylab::test {

using stats::ChiSquareResult;
using stats::chiSquarePValue;
using stats::chiSquareTest;
using stats::gammaQ;
using stats::mean;
using stats::sidak;
using stats::slope;
using stats::standardError;

} // namespace raylab::test
