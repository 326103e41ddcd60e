#pragma once
// The GLSL sampler harness lives in src/selftest (the viewer's self-test runs it too).
#include "selftest/gpu_sampler.h"

namespace raylab::test {

using raylab::GpuSample;
using raylab::GpuSampler;

} // namespace raylab::test
