// Scene features the tracer is specialised for, so that a scene pays nothing for code it does not
// need (bench/geometry.md, "Specialised against all-features shader"). RAYLAB_FEATURE_LIST is the
// one list: the host's SceneFeatures, its defines and names (render/shader_variant.cpp) and
// kTracerDefines (render/tracer_defines.h) are generated from it. The host emits every feature as 0 or 1 right after #version and shaders test
// them with #if; a shader compiled without them stops. C++ (the shared maths of compat.glsl) sees
// the defaults below, which are also SceneFeatures' defaults: the unspecialised tracer.
#ifndef RAYLAB_FEATURES_GLSL
#define RAYLAB_FEATURES_GLSL

#ifdef __cplusplus
// RL_FEATURE(define, SceneFeatures field, needs, name in variant names): the define is 1 when the
// field and the field `needs` names are both true (`always`: no prerequisite).
#define RAYLAB_FEATURE_LIST(RL_FEATURE)                                                          \
    RL_FEATURE(RAYLAB_FEATURE_SPHERES, spheres, always, "spheres")                               \
    RL_FEATURE(RAYLAB_FEATURE_MESHES, meshes, always, "meshes")                                  \
    RL_FEATURE(RAYLAB_FEATURE_SMOOTH_NORMALS, smoothNormals, always, "smooth")                   \
    RL_FEATURE(RAYLAB_FEATURE_DOF, depthOfField, always, "dof")                                  \
    RL_FEATURE(RAYLAB_FEATURE_TEXTURES, textures, always, "textures")                            \
    RL_FEATURE(RAYLAB_TOP_LEVEL_LINEAR, linearTopLevel, always, "few-objects")                   \
    RL_FEATURE(RAYLAB_SMALL_MESHES, smallMeshes, linearTopLevel, "small-meshes")                 \
    RL_FEATURE(RAYLAB_MESHES_IN_WORLD, meshesInWorld, smallMeshes, "meshes-in-world")          \
    RL_FEATURE(RAYLAB_SHOW_MIP_LEVEL, showMipLevel, always, "mip-view")                          \
    RL_FEATURE(RAYLAB_NEE, nee, always, "nee")                                                   \
    RL_FEATURE(RAYLAB_GENERAL_BSDF, generalBsdf, always, "ggx+glass")                            \
    RL_FEATURE(RAYLAB_SKY_MAP, skyMap, always, "sky-map")                                        \
    RL_FEATURE(RAYLAB_TEXTURE_ROUGHNESS, roughnessTextures, textures, "roughness-tex")           \
    RL_FEATURE(RAYLAB_TEXTURE_METALLIC, metallicTextures, textures, "metallic-tex")              \
    RL_FEATURE(RAYLAB_TEXTURE_EMISSION, emissionTextures, textures, "emission-tex")              \
    RL_FEATURE(RAYLAB_TEXTURE_SPECULAR, specularTextures, textures, "specular-tex")              \
    RL_FEATURE(RAYLAB_TEXTURE_WRAP_MODES, textureWrapModes, textures, "wrap-modes")              \
    RL_FEATURE(RAYLAB_EMISSIVE_TRIANGLES, emissiveTriangles, always, "triangle-lights")          \
    RL_FEATURE(RAYLAB_SPHERE_LIGHTS, sphereLights, always, "sphere-lights")                      \
    RL_FEATURE(RAYLAB_SKY_LIGHT, skyLight, always, "sky-light")                                  \
    RL_FEATURE(RAYLAB_LIGHT_POWER_SELECTION, lightPowerSelection, always, "light-power")         \
    RL_FEATURE(RAYLAB_ANALYTIC_LIGHTS, analyticLights, always, "point-spot-sun")                 \
    RL_FEATURE(RAYLAB_ONE_SIDED_EMITTERS, oneSidedEmitters, always, "one-sided")                 \
    RL_FEATURE(RAYLAB_ADAPTIVE, adaptive, always, "adaptive")

#define RAYLAB_FEATURES_SPECIALISED 1
#define RAYLAB_FEATURE_SPHERES 1          // the scene has spheres
#define RAYLAB_FEATURE_MESHES 1           // the scene has triangle meshes
#define RAYLAB_FEATURE_SMOOTH_NORMALS 1   // some mesh has per-vertex normals
#define RAYLAB_FEATURE_DOF 1              // the camera has a lens (camera.aperture > 0)
#define RAYLAB_FEATURE_TEXTURES 1         // some material has an image texture
#define RAYLAB_TOP_LEVEL_LINEAR 0         // few objects: a loop over them instead of the top-level BVH
#define RAYLAB_SMALL_MESHES 0             // with few objects, every mesh small: its triangles tested without its BVH
#define RAYLAB_MESHES_IN_WORLD 0          // with small meshes, every mesh's vertices in world space, placed by the identity
#define RAYLAB_SHOW_MIP_LEVEL 0           // debug view render.show_mip_level (with textures)
#define RAYLAB_NEE 1                      // next-event estimation (render.nee)
#define RAYLAB_GENERAL_BSDF 1             // GGX specular and glass (some material has f0 or transmission)
#define RAYLAB_SKY_MAP 1                  // an HDR environment image (sky.type map)
#define RAYLAB_TEXTURE_ROUGHNESS 1        // some material has a roughness texture
#define RAYLAB_TEXTURE_METALLIC 1         // metallic mixed per hit (render/gpu_scene.h metallicOnGpu)
#define RAYLAB_TEXTURE_EMISSION 1         // some material has an emission texture
#define RAYLAB_TEXTURE_SPECULAR 1         // some material has a specular (f0) texture
#define RAYLAB_TEXTURE_WRAP_MODES 1       // some texture clamps or mirrors instead of repeating (glTF)
#define RAYLAB_EMISSIVE_TRIANGLES 1       // with NEE: some mesh emits, its triangles are lights
#define RAYLAB_SPHERE_LIGHTS 1            // with NEE: some sphere emits, a light sampled by its cone
#define RAYLAB_SKY_LIGHT 1                // with NEE: the sky may emit (a map, or a colour above 0), a light
#define RAYLAB_LIGHT_POWER_SELECTION 1    // with NEE: lights differ in power, picked by power
#define RAYLAB_ANALYTIC_LIGHTS 1          // the scene has point, spot or distant lights (scene `lights`)
#define RAYLAB_ONE_SIDED_EMITTERS 1       // some mesh emits on its front side only (emission_sides front)
#define RAYLAB_ADAPTIVE 0                 // render.adaptive: samples per block as the host plans them (adaptive_sampling.glsl)
#elif !defined(RAYLAB_FEATURES_SPECIALISED)
#error "compiled without the scene's feature defines: pass featureDefines() (render/shader_variant.h)"
#endif

// With few objects (RAYLAB_TOP_LEVEL_LINEAR) the host fixes how many there are (spheres and meshes)
// and how many of them are spheres, so the object loops have trip counts the compiler knows: they
// are unrolled, and each object's record is read from the few-objects block (few_objects.glsl) at
// a constant offset (bench/mesh_rays.md, "Few objects in a uniform block"). 0: the loops read the
// buffers' lengths.
#ifndef RAYLAB_OBJECT_COUNT
#define RAYLAB_OBJECT_COUNT 0
#endif
#ifndef RAYLAB_SPHERE_COUNT
#define RAYLAB_SPHERE_COUNT 0
#endif
// The teaching stages of render.stage (scene.h RenderStage): each adds to the one before. The host
// sets RAYLAB_STAGE to one of them; test shaders of the geometry alone may leave it out.
#define RAYLAB_STAGE_PRIMARY 0    // flat albedo of the first hit
#define RAYLAB_STAGE_EMISSION 1   // + emitters and sky seen directly
#define RAYLAB_STAGE_LAMBERT 2    // + path tracing, every material Lambertian
#define RAYLAB_STAGE_GGX 3        // + the general BSDF (the host also sets RAYLAB_GENERAL_BSDF)
#define RAYLAB_STAGE_TEXTURES 4   // + textures (RAYLAB_FEATURE_TEXTURES)
#define RAYLAB_STAGE_FULL 5       // + depth of field (RAYLAB_FEATURE_DOF)
#ifndef RAYLAB_STAGE
#define RAYLAB_STAGE RAYLAB_STAGE_FULL
#endif

// How a path's random numbers are made (render.sampler, scene.h SamplerKind; sampler.glsl). The
// host sets RAYLAB_SAMPLER to one of them, so a variant holds only its own sampler's code.
#define RAYLAB_SAMPLER_INDEPENDENT 0   // hashed PCG streams, numbers taken in call order
#define RAYLAB_SAMPLER_STRATIFIED 1    // jittered strata in a per-pixel random order
#define RAYLAB_SAMPLER_SOBOL 2         // Owen-scrambled Sobol (Burley 2020)
#define RAYLAB_SAMPLER_ZSOBOL 3        // Sobol over Morton-ordered pixels (Ahmed & Wonka 2020)
#ifndef RAYLAB_SAMPLER
#define RAYLAB_SAMPLER RAYLAB_SAMPLER_INDEPENDENT
#endif

#endif
