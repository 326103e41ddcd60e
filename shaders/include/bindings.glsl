// Every buffer binding point, image unit and texture unit the host and the shaders agree on, for
// both C++ and GLSL (preprocessor only, so layout(binding = ...) can use them). A new buffer is one
// line here; tests/render/bindings_test.cpp checks that no two share a point within a program.
#ifndef RAYLAB_BINDINGS_GLSL
#define RAYLAB_BINDINGS_GLSL

// Images and textures.
#define BINDING_ACCUM_IMAGE 0          // image unit: the running mean, RGBA32F (tracer)
#define BINDING_ACCUM_TEXTURE 0        // texture unit: the running mean, read by the display pass
#define BINDING_SAMPLE_PLAN_IMAGE 1    // image unit: render.adaptive's plan, R32UI (adaptive_sampling.glsl)
#define BINDING_ADAPTIVE_HALF_IMAGE 2  // image unit: render.adaptive's half mean and rays per sample, RGBA32F
#define BINDING_SKY_MAP_TEXTURE 4      // texture unit: sky.map (1×1 black without)
// Texture units: texture-buffer views of geometry buffers, RGBA32UI (scene_geometry.glsl).
#define BINDING_TOP_NODE_TEXELS 5
#define BINDING_MESH_NODE_TEXELS 6
#define BINDING_INSTANCE_TEXELS 7
#define BINDING_TRIANGLE_TEXELS 8
#define BINDING_TEXTURE_TEXELS 9      // texture unit: every texture's texels, RGBA32UI (scene_textures.glsl)
#define BINDING_MATERIAL_TEXELS 10    // texture unit: the materials' records, RGBA32UI (scene_data.glsl)
// Texture units: texture-buffer views of the light buffers (scene_data.glsl).
#define BINDING_TRIANGLE_LIGHT_TEXELS 11        // the emissive triangles' records, RGBA32UI
#define BINDING_LIGHT_ALIAS_TEXELS 12           // the alias table over every light, RGBA32UI
#define BINDING_TRIANGLE_LIGHT_INDEX_TEXELS 13  // each triangle's light index, R32UI

// The tracer's storage buffers (shaders/include/scene_data.glsl, scene_geometry.glsl,
// scene_textures.glsl; filled by src/render/gpu_scene.cpp and path_tracer.cpp).
#define BINDING_SPHERES 1
#define BINDING_MATERIALS 2
#define BINDING_COUNTERS 3             // non-finite samples and rays traced this pass
#define BINDING_SPHERE_LIGHTS 4
#define BINDING_ENV_MARGINAL 5         // sky map importance sampling: marginal CDF over rows
#define BINDING_ENV_CONDITIONAL 6      // and the conditional CDFs over columns
#define BINDING_TOP_NODES 8
#define BINDING_MESH_NODES 9
#define BINDING_INSTANCES 10
#define BINDING_TRIANGLES 11
#define BINDING_VERTICES 12
#define BINDING_TRAVERSAL_COUNTERS 13  // RAYLAB_COUNT_TRAVERSAL: boxes and triangles tested
#define BINDING_TEXTURE_INFO 15
#define BINDING_ADAPTIVE_BLOCKS 27     // render.adaptive: the blocks a draw traces, in strip order (fragment_layout.glsl)

// Debug variants and the display pass.
#define BINDING_DEBUG_MOMENTS 16       // per-pixel moments for the noise and NaN views
#define BINDING_DEBUG_HEAT_MAX 17      // largest box / triangle count of one camera ray

// The pixel path inspector (RAYLAB_INSPECT_PATHS).
#define BINDING_INSPECT_BOUNCES 20
#define BINDING_INSPECT_PATHS 21

// Uniform buffers (a namespace of their own): the parameter blocks.
#define BINDING_TRACER_PARAMS_UBO 0    // the tracer's parameters (TracerParams)
#define BINDING_DEBUG_PARAMS_UBO 1     // the debug views' parameters
#define BINDING_DISPLAY_PARAMS_UBO 2   // the display pass's parameters
#define BINDING_ANALYTIC_LIGHTS_UBO 3  // point, spot and distant lights (analytic_lights.glsl)
#define BINDING_FEW_OBJECTS_UBO 4      // with few objects, their boxes and spheres (few_objects.glsl)

// Programs of their own: the self-test's sampler (entry/bsdf_samples.comp), test shaders and the
// exercise probe (entry/exercise_probe.comp).
#define BINDING_BSDF_SAMPLES 7
#define BINDING_TEST_INPUT 14
#define BINDING_TEST_OUTPUT 15

// The ray-rate benchmark's program (entry/ray_cast.frag), bound beside the scene's geometry.
#define BINDING_CAST_RAYS 28
#define BINDING_CAST_HITS 29

#endif
