#pragma once
// Per-scene specialisation of the tracer: the features a scene uses become #defines right after
// #version (shaders/include/features.glsl), so absent features cost nothing at run time
// (bench/geometry.md); compiled variants are cached by their define set.
#include "gl/shader_program.h"
#include "scene/scene.h"
#include "shaders/include/features.glsl"
#include "shaders/include/few_objects.glsl"

#include <cstdint>
#include <map>
#include <string>

namespace raylab {

// One field per entry of RAYLAB_FEATURE_LIST (features.glsl, where each is described), defaulting
// to the unspecialised tracer's value.
struct SceneFeatures {
#define RL_FEATURE_FIELD(def, field, needs, name) bool field = def;
    RAYLAB_FEATURE_LIST(RL_FEATURE_FIELD)
#undef RL_FEATURE_FIELD
    RenderStage stage = RenderStage(RAYLAB_STAGE);   // render.stage below full: RAYLAB_STAGE (teaching)
    SamplerKind sampler = SamplerKind(RAYLAB_SAMPLER);   // render.sampler: RAYLAB_SAMPLER
    DiffuseSampling diffuseSampling = DiffuseSampling(RAYLAB_DIFFUSE_SAMPLING);   // RAYLAB_DIFFUSE_SAMPLING
    GgxSampling ggxSampling = GgxSampling(RAYLAB_GGX_SAMPLING);                   // RAYLAB_GGX_SAMPLING
    LightSampling lightSampling = LightSampling(RAYLAB_LIGHT_SAMPLING);           // RAYLAB_LIGHT_SAMPLING
    Accel accel = Accel(RAYLAB_ACCEL);                                            // RAYLAB_ACCEL
    bool flatSteps = RAYLAB_FLAT_STEPS;   // boxes/none with a large mesh: RAYLAB_FLAT_STEPS
    // With few objects their number and how many are spheres, else 0: RAYLAB_OBJECT_COUNT, _SPHERE_COUNT.
    int objectCount = RAYLAB_OBJECT_COUNT;
    int sphereCount = RAYLAB_SPHERE_COUNT;
    static constexpr bool always = true;   // the `needs` of a feature without a prerequisite
    bool usesFlatSteps() const { return flatSteps && accel != Accel::Bvh; }   // the BVH has no flat search
    bool operator==(const SceneFeatures&) const = default;
};

// Up to this many objects the top level is a plain loop (bench/geometry.md measured it faster).
constexpr std::size_t kLinearTopLevelMax = std::size_t(glsl::FEW_OBJECTS_MAX);
static_assert(kLinearTopLevelMax <= 32, "the few-objects loop keeps a bit per object in a uint (bvh_traversal.glsl)");

// Up to this many triangles a mesh of a few-object scene is searched without its BVH: its triangles
// straight after its world box (RAYLAB_SMALL_MESHES; bench/mesh_rays.md measured it cheaper).
constexpr std::size_t kSmallMeshMax = 16;

// llvmpipe ends all loops of a shader invocation after this many iterations in all (gallivm's loop
// limiter; PathTracer sizes its draws by it).
constexpr std::uint64_t kLoopIterationBudget = 65535;

// Loop iterations one sample can spend at most in a flat search (render.accel boxes or none): a
// traced and a shadow ray per bounce (or ao.rays rays of the AO view), each stepping through every
// object and each mesh's triangles, with `steps` in whole steps of FLAT_TRIANGLES_PER_STEP and the
// rest one at a time. 0 for the BVH.
std::uint64_t flatLoopIterationsPerSample(const Scene& scene, bool steps);

// Loop iterations one sample can spend at most in the variant `features` of `scene` where every
// loop's trip count has a bound: a flat search, or few objects whose meshes are all small (their
// triangles tested without a BVH walk). The searches as flatLoopIterationsPerSample counts them,
// plus the path loop's step per bounce, a step per distant light at an escape, and the samplers'
// own loops (zsobol's digits; stratified's cycle walk, about two per number). 0 where a BVH walk
// has no such bound. `extraDefines`: a variant of the debug views, the inspector or the traversal
// counts (which walks small meshes' BVHs too); only a flat search's bound is taken for those.
std::uint64_t boundedLoopIterationsPerSample(const Scene& scene, const SceneFeatures& features, bool extraDefines);

SceneFeatures sceneFeatures(const Scene& scene);   // what this scene needs
SceneFeatures allFeatures();                       // the unspecialised tracer
// RAYLAB_FEATURES_SPECIALISED, every feature of the list as 0 or 1, RAYLAB_STAGE, RAYLAB_SAMPLER and
// the estimator stages of estimator_stages.glsl.
ShaderDefines featureDefines(const SceneFeatures& features);
// "spheres+meshes+dof", "none" when nothing is on; a sampler other than independent is named too,
// and so is an estimator stage other than the default.
std::string featureName(const SceneFeatures& features);

// Compiled programs by define set. Needs a current GL context; programs live as long as the cache.
class ShaderVariantCache {
public:
    using Compile = ShaderProgram (*)(const ShaderDefines&, const void* context);
    // The program for `defines`, compiled on first use by compile(defines, context).
    const ShaderProgram& get(const ShaderDefines& defines, Compile compile, const void* context);
    std::size_t size() const { return programs_.size(); }

private:
    std::map<std::string, ShaderProgram> programs_;
};

} // namespace raylab
