#pragma once
// The tests' name for the GPU sampler (src/inspect/gpu_bsdf_sampler.h, which the viewer's BRDF
// explorer uses too): samples drawn by the real GLSL sampling code on the current GL context.
#include "inspect/gpu_bsdf_sampler.h"

namespace raylab::test {

using GpuSample = raylab::GpuSample;
using GpuSampler = raylab::GpuBsdfSampler;

} // namespace raylab::test
