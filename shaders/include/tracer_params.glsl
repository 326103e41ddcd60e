// The tracer's parameters, declared once for both sides: in GLSL the std140 uniform block
// TracerParams and the shader's copy of it, `params`; in C++ the struct render/path_tracer.cpp
// fills and uploads whole. Every vec3 starts on 16 bytes and a scalar fills its fourth slot, so
// the C++ offsets are the std140 ones (Falcor's Params.slang pads the same way);
// tests/render/tracer_params_layout_test.cpp compares them with the driver's.
#ifndef RAYLAB_TRACER_PARAMS_GLSL
#define RAYLAB_TRACER_PARAMS_GLSL
#include "compat.glsl"
#include "bindings.glsl"

// The fields in block order, each X(type, name) with its meaning: the one list the C++ struct,
// the GLSL block and the shader's copy of it are made from.
#define RAYLAB_TRACER_PARAMS(X)                                                                                 \
    X(uint, sampleStart)          /* samples per pixel already in uAccum (per band) */                          \
    X(int, rpp)                   /* samples per pixel in this band (per band) */                               \
    X(ivec2, imageSize)           /* pixels */                                                                  \
    X(uint, seed)                                                                                               \
    X(int, maxBounces)                                                                                          \
    X(int, rrDepth)               /* first bounce that may end by Russian roulette */                           \
    X(int, sphereCount)                                                                                         \
    X(vec3, camOrigin)                                                                                          \
    X(float, camTanHalfFovY)                                                                                    \
    X(vec3, camRight)             /* unit, image +x */                                                          \
    X(float, camAspect)           /* width / height */                                                          \
    X(vec3, camUp)                /* unit, image +y */                                                          \
    X(float, camLensRadius)       /* thin lens (RAYLAB_FEATURE_DOF): lens radius, world units */                \
    X(vec3, camForward)           /* unit, viewing direction */                                                 \
    X(float, camFocusDistance)    /* distance of the sharp plane along the view axis */                         \
    X(vec3, skyColor)             /* constant sky: radiance (times sky.strength) */                             \
    X(float, camPixelSpread)      /* angle one pixel subtends (ray-cone texture LOD), radians */                \
    X(vec3, skyTop)               /* gradient sky: radiance towards +y (times sky.strength) */                  \
    X(int, skyType)               /* SKY_CONSTANT, SKY_GRADIENT or SKY_MAP (sky.glsl) */                        \
    X(vec3, skyBottom)            /* gradient sky: radiance towards -y (times sky.strength) */                  \
    X(float, skyMapScale)         /* sky.strength for the map */                                                \
    X(float, skyRotation)         /* radians about +y */                                                        \
    X(float, envMeanWeight)       /* mean texel weight of the sky map's distribution; 0 = none */               \
    X(int, lightCount)            /* emissive spheres in lights[] */                                            \
    X(int, triangleLightCount)    /* emissive triangles (triangleLightAt) */                                     \
    X(RL_BLOCK_BOOL, nee)         /* next-event estimation on */                                                \
    X(RL_BLOCK_BOOL, mis)         /* with nee: power-heuristic MIS of light and BSDF samples */                 \
    X(RL_BLOCK_BOOL, skyIsLight)  /* with nee: the sky is sampled too (its radiance is not zero) */             \
    X(uint, sampleCount)          /* render.spp: samples per pixel in all (stratified's strata) */              \
    X(float, aoDistance)          /* ao.distance: the ambient-occlusion view's reach, world units */            \
    X(int, aoRays)                /* ao.rays: its rays per camera sample */                                     \
    X(int, fragmentStripTiles)    /* fragment entry: the draw's strip's tiles (fragment_layout.glsl); 0 none */ \
    X(int, fragmentStripBlocks)   /* render.adaptive: blocks in adaptiveBlocks[] for this draw; 0 none */

// A GLSL bool in a uniform block is 4 bytes, 0 false.
#define RL_PARAM_MEMBER(type, name) type name;
#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#define RL_BLOCK_BOOL std::uint32_t
RL_NAMESPACE_BEGIN
struct TracerParams {
    RAYLAB_TRACER_PARAMS(RL_PARAM_MEMBER)
};

static_assert(sizeof(vec3) == 12 && sizeof(ivec2) == 8, "GLM must not pad its vectors");
static_assert(offsetof(TracerParams, imageSize) % 8 == 0);
static_assert(offsetof(TracerParams, camOrigin) % 16 == 0 && offsetof(TracerParams, camRight) % 16 == 0 &&
              offsetof(TracerParams, camUp) % 16 == 0 && offsetof(TracerParams, camForward) % 16 == 0 &&
              offsetof(TracerParams, skyColor) % 16 == 0 && offsetof(TracerParams, skyTop) % 16 == 0 &&
              offsetof(TracerParams, skyBottom) % 16 == 0, "std140: a vec3 starts on 16 bytes");
static_assert(offsetof(TracerParams, rpp) == offsetof(TracerParams, sampleStart) + 4,
              "the per-band fields are uploaded as one range");
static_assert(offsetof(TracerParams, fragmentStripBlocks) == offsetof(TracerParams, fragmentStripTiles) + 4,
              "the strip's fields are uploaded as one range");
static_assert(sizeof(TracerParams) % 16 == 0, "std140: a block is whole vec4s");
RL_NAMESPACE_END
#else
#define RL_BLOCK_BOOL bool
layout(std140, binding = BINDING_TRACER_PARAMS_UBO) uniform TracerParams {
    RAYLAB_TRACER_PARAMS(RL_PARAM_MEMBER)
} paramsBlock;

// The shader reads `params`, the invocation's copy of the block, made field by field before main
// runs (a global's initialiser): llvmpipe (Mesa 22.3) reads a uniform block lane by lane with a
// bounds check per lane, so a block field read inside the path loop cost a gather on every
// bounce, where the copy is a register or a stack slot (bench/mesh_rays.md, "Uniform blocks
// copied once an invocation"). Field by field, as a whole-block copy is forwarded back to reads
// of the block where the copy is used.
struct TracerParamsValues {
    RAYLAB_TRACER_PARAMS(RL_PARAM_MEMBER)
};
#define RL_PARAM_COPY(type, name) p.name = paramsBlock.name;
TracerParamsValues loadTracerParams() {
    TracerParamsValues p;
    RAYLAB_TRACER_PARAMS(RL_PARAM_COPY)
    return p;
}
#undef RL_PARAM_COPY
TracerParamsValues params = loadTracerParams();
#endif
#undef RL_PARAM_MEMBER
#undef RL_BLOCK_BOOL

#endif
