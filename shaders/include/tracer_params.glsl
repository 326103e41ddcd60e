// The tracer's parameters, declared once for both sides: in GLSL the std140 uniform block
// `params`, in C++ the struct render/path_tracer.cpp fills and uploads whole. Every vec3 starts on
// 16 bytes and a scalar fills its fourth slot, so the C++ offsets are the std140 ones (Falcor's
// Params.slang pads the same way); tests/render/tracer_params_layout_test.cpp compares them with
// the driver's.
#ifndef RAYLAB_TRACER_PARAMS_GLSL
#define RAYLAB_TRACER_PARAMS_GLSL
#include "compat.glsl"
#include "bindings.glsl"

// A GLSL bool in a uniform block is 4 bytes, 0 false.
#ifdef __cplusplus
#include <cstddef>
#include <cstdint>
#define RL_BLOCK_BOOL std::uint32_t
RL_NAMESPACE_BEGIN
struct TracerParams {
#else
#define RL_BLOCK_BOOL bool
layout(std140, binding = BINDING_TRACER_PARAMS_UBO) uniform TracerParams {
#endif
    uint sampleStart;          // samples per pixel already in uAccum (per band)
    int rpp;                   // samples per pixel in this band (per band)
    ivec2 imageSize;           // pixels
    uint seed;
    int maxBounces;
    int rrDepth;               // first bounce that may end by Russian roulette
    int sphereCount;
    vec3 camOrigin;
    float camTanHalfFovY;
    vec3 camRight;             // unit, image +x
    float camAspect;           // width / height
    vec3 camUp;                // unit, image +y
    float camLensRadius;       // thin lens (RAYLAB_FEATURE_DOF): lens radius, world units
    vec3 camForward;           // unit, viewing direction
    float camFocusDistance;    // distance of the sharp plane along the view axis
    vec3 skyColor;             // constant sky: radiance (times sky.strength)
    float camPixelSpread;      // angle one pixel subtends (ray-cone texture LOD), radians
    vec3 skyTop;               // gradient sky: radiance towards +y (times sky.strength)
    int skyType;               // SKY_CONSTANT, SKY_GRADIENT or SKY_MAP (sky.glsl)
    vec3 skyBottom;            // gradient sky: radiance towards -y (times sky.strength)
    float skyMapScale;         // sky.strength for the map
    float skyRotation;         // radians about +y
    float envMeanWeight;       // mean texel weight of the sky map's distribution; 0 = none
    int lightCount;            // emissive spheres in lights[]
    int triangleLightCount;    // emissive triangles in triangleLights[]
    RL_BLOCK_BOOL nee;         // next-event estimation on
    RL_BLOCK_BOOL mis;         // with nee: power-heuristic MIS of light and BSDF samples
    RL_BLOCK_BOOL skyIsLight;  // with nee: the sky is sampled too (its radiance is not zero)
    uint sampleCount;          // render.spp: samples per pixel of the whole render (stratified strata)
    float aoDistance;          // ao.distance: the ambient-occlusion view's reach, world units
    int aoRays;                // ao.rays: its rays per camera sample
    int fragmentStripTiles;    // fragment entry: tiles of the strip the draw fills (fragment_layout.glsl); 0 none
    int fragmentStripBlocks;   // fragment entry, render.adaptive: blocks listed in adaptiveBlocks[] for this draw; 0 none
#ifdef __cplusplus
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
} params;
#endif
#undef RL_BLOCK_BOOL

#endif
