// One progressive pass of the path tracer for one pixel, shared by both entry points
// (trace.frag, trace.comp): params.rpp new samples join the pixel's running mean in uAccum. GLSL only.
#ifndef RAYLAB_PATH_TRACER_GLSL
#define RAYLAB_PATH_TRACER_GLSL
#include "compat.glsl"
#include "features.glsl"
#include "sampler.glsl"
#include "camera.glsl"
#include "scene_data.glsl"
#include "adaptive_sampling.glsl"
// The viewer's debug views and moments; empty unless the host defines RAYLAB_DEBUG_VIEWS or
// RAYLAB_DEBUG_MOMENTS. Before the integrator, whose radiance hook it may set.
#include "debug_views.glsl"
#include "integrator.glsl"
#ifdef RAYLAB_EXERCISE_RUNNING_MEAN
#include RAYLAB_EXERCISE_RUNNING_MEAN   // a pupil's runningMean (exercises/README.md)
#endif

// The sampler of the pass's sample s of a pixel whose mean holds `start` samples.
Sampler passSampler(ivec2 pixel, uint start, int s) {
    return samplerCreate(uvec2(pixel), start + uint(s), params.seed, params.sampleCount);
}

// A camera ray through a fresh position inside the pixel (box filter), through the lens with DOF.
Ray cameraSample(CameraBasis cam, ivec2 pixel, inout Sampler smp) {
    vec2 ndc = (vec2(pixel) + sample2D(smp, SAMPLE_DIM_PIXEL)) / vec2(params.imageSize) * 2.0f - 1.0f;
#if RAYLAB_FEATURE_DOF
    return cameraRayThinLens(cam, ndc, sample2D(smp, SAMPLE_DIM_LENS), params.camLensRadius, params.camFocusDistance);
#else
    return cameraRay(cam, ndc);
#endif
}

#if RAYLAB_DEBUG_MOMENTS
#define RAYLAB_MOMENTS_ARG , inout DebugMoments moments
#define RAYLAB_MOMENTS , moments
#else
#define RAYLAB_MOMENTS_ARG
#define RAYLAB_MOMENTS
#endif

// Sample s's radiance L into the pass's sum; a NaN or infinite one is dropped and counted. Returns
// what was added.
vec3 addSample(vec3 L, int s, ivec2 pixel, inout vec3 sum, inout uint nonFinite RAYLAB_MOMENTS_ARG) {
#if RAYLAB_INJECT_NONFINITE
    // Tests only: every RAYLAB_INJECT_NONFINITE-th sample of a row becomes NaN or +Inf.
    uint k = params.sampleStart + uint(s) + uint(pixel.x);
    if (k % uint(RAYLAB_INJECT_NONFINITE) == 0u)
        L = vec3(uintBitsToFloat((k & 1u) == 0u ? 0x7fc00000u : 0x7f800000u));
#endif
#if RAYLAB_DEBUG_MOMENTS
    debugMomentsAdd(moments, L);
#endif
    if (any(isnan(L)) || any(isinf(L))) {
        ++nonFinite;
        L = vec3(0.0f);
    }
    sum += L;
    return L;
}

void tracePixelPass(ivec2 pixel) {
#if RAYLAB_ADAPTIVE
    // The host's plan (adaptive_sampling.glsl): this pixel's samples so far, or a pass it sits out;
    // params.sampleStart is then the draw's offset within the pass.
    uint planned = imageLoad(uSamplePlan, pixel).r;
    if (planned == ADAPTIVE_SKIP) return;
    uint start = planned + params.sampleStart;
    vec3 sumHalf = vec3(0.0f);
#else
    uint start = params.sampleStart;
#endif
    CameraBasis cam = CameraBasis(params.camOrigin, params.camRight, params.camUp, params.camForward,
                                  params.camTanHalfFovY, params.camAspect);
    vec3 sum = vec3(0.0f);
    uint rays = 0u;
    uint nonFinite = 0u;
#if RAYLAB_DEBUG_MOMENTS
    DebugMoments moments = debugMomentsBegin();
#endif
#if RAYLAB_DEBUG_VIEWS || RAYLAB_INSPECT_PATHS
    for (int s = 0; s < params.rpp; ++s) {
        Sampler smp = passSampler(pixel, start, s);
        Ray cameraPath = cameraSample(cam, pixel, smp);
        RAYLAB_RECORD_PATH_BEGIN(pixel, s, cameraPath);
#if RAYLAB_DEBUG_VIEWS
        vec3 L = debugSample(cameraPath, smp, rays);
#else
        vec3 L = traceRadiance(cameraPath, smp, rays);
#endif
        RAYLAB_RECORD_PATH_END(pixel, s, L);
        addSample(L, s, pixel, sum, nonFinite RAYLAB_MOMENTS);
    }
#else
    // Path regeneration (Novák, Havran and Dachsbacher 2010, "Path Regeneration for Interactive
    // Path Tracing"): one loop over the bounces of the pass's rpp samples, so an invocation whose
    // path ended starts its next sample at once. Invocations run in SIMD batches that last as long
    // as their longest loop: per sample, a batch would wait for its longest path every time. Each
    // sample's radiance and the sum's order are as the plain loop has them.
    int s = 0;
    Sampler smp = passSampler(pixel, start, 0);
    PathState path = pathStart(cameraSample(cam, pixel, smp));
    while (s < params.rpp) {
        if (!pathStep(path, smp, rays)) continue;
        vec3 added = addSample(path.radiance, s, pixel, sum, nonFinite RAYLAB_MOMENTS);
#if RAYLAB_ADAPTIVE
        if (adaptiveInHalf(start + uint(s))) sumHalf += added;
#endif
        if (++s < params.rpp) {
            smp = passSampler(pixel, start, s);
            path = pathStart(cameraSample(cam, pixel, smp));
        }
    }
#endif
    // Running mean over all samples: mean_n = mean_m + (sum − k·mean_m) / n, with n = m + k.
#ifdef RAYLAB_EXERCISE_RUNNING_MEAN
    vec3 old = start > 0u ? imageLoad(uAccum, pixel).rgb : vec3(0.0f);
    vec3 mean = runningMean(old, start, sum, uint(params.rpp));
#else
    vec3 mean = sum / float(params.rpp);
    if (start > 0u) {
        vec3 old = imageLoad(uAccum, pixel).rgb;
        mean = old + (sum - float(params.rpp) * old) / float(start + uint(params.rpp));
    }
#endif
    imageStore(uAccum, pixel, vec4(mean, 1.0f));
#if RAYLAB_ADAPTIVE
    // The half's mean and the rays per sample, running means as the image's.
    uint end = start + uint(params.rpp);
    uint halfBefore = adaptiveHalfCount(start), halfAfter = adaptiveHalfCount(end);
    vec4 stored = start > 0u ? imageLoad(uAdaptiveHalf, pixel) : vec4(0.0f);
    vec3 halfMean = halfAfter == 0u ? vec3(0.0f)
                  : stored.rgb + (sumHalf - float(halfAfter - halfBefore) * stored.rgb) / float(halfAfter);
    float raysPerSample = stored.a + (float(rays) - float(params.rpp) * stored.a) / float(end);
    imageStore(uAdaptiveHalf, pixel, vec4(halfMean, raysPerSample));
#endif
    // llvmpipe (gallivm) ends every loop of an invocation once 65535 loop iterations have run in
    // all, silently. A loop of rpp + 1 iterations that stops early shows the budget ran out, so
    // the host can report it and draw fewer samples per invocation (PathTracer::traceBand).
    uint probe = 0u;
    for (int i = 0; i <= params.rpp; ++i) ++probe;
    if (probe <= uint(params.rpp)) atomicAdd(loopLimited, 1u);
#if RAYLAB_DEBUG_MOMENTS
    debugMomentsStore(moments, pixel);
#endif
    if (nonFinite > 0u) atomicAdd(nonFiniteSamples, nonFinite);
    atomicAdd(raysTraced, rays);
#if RAYLAB_COUNT_TRAVERSAL
    atomicAdd(boxTestsTotal, gBoxTests);
    atomicAdd(triangleTestsTotal, gTriangleTests);
#endif
}

#endif
