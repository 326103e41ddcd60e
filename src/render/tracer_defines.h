#pragma once
// Every #define the host can set on the path tracer's entry points (shaders/entry/trace.frag and
// trace.comp), in one list; the scene's features come from RAYLAB_FEATURE_LIST. Host code names a
// define through tracerDefine("NAME"), which does not compile for a name that is missing here, and
// tests/render/tracer_defines_test.cpp fails on a shader that tests a name missing here.
#include "shaders/include/features.glsl"

#include <string_view>

namespace raylab {

struct TracerDefine {
    std::string_view name;
    std::string_view setBy;    // where the host sets it
    bool computeOnly = false;  // trace.comp only
};

inline constexpr TracerDefine kTracerDefines[] = {
    // The scene's features (render/shader_variant.cpp featureDefines; shaders/include/features.glsl).
    {"RAYLAB_FEATURES_SPECIALISED", "render/shader_variant.cpp"},
#define RL_FEATURE_ENTRY(def, field, needs, name) {#def, "render/shader_variant.cpp"},
    RAYLAB_FEATURE_LIST(RL_FEATURE_ENTRY)
#undef RL_FEATURE_ENTRY
    {"RAYLAB_STAGE", "render/shader_variant.cpp"},
    {"RAYLAB_SAMPLER", "render/shader_variant.cpp"},
    {"RAYLAB_DIFFUSE_SAMPLING", "render/shader_variant.cpp"},
    {"RAYLAB_GGX_SAMPLING", "render/shader_variant.cpp"},
    {"RAYLAB_LIGHT_SAMPLING", "render/shader_variant.cpp"},
    {"RAYLAB_ACCEL", "render/shader_variant.cpp"},
    {"RAYLAB_FLAT_STEPS", "render/shader_variant.cpp"},
    {"RAYLAB_OBJECT_COUNT", "render/shader_variant.cpp"},
    {"RAYLAB_SPHERE_COUNT", "render/shader_variant.cpp"},
    // The compute entry's work-group size (render/path_tracer.cpp).
    {"LOCAL_SIZE_X", "render/path_tracer.cpp", true},
    {"LOCAL_SIZE_Y", "render/path_tracer.cpp", true},
    // Debug variants (TracerOptions::extraDefines).
    {"RAYLAB_DEBUG_VIEWS", "render/tracer_variants.cpp"},
    {"RAYLAB_DEBUG_MOMENTS", "render/tracer_variants.cpp"},
    {"RAYLAB_COUNT_TRAVERSAL", "render/tracer_variants.cpp"},
    {"RAYLAB_INSPECT_PATHS", "inspect/path_inspector.cpp"},
    // The code track's slots, each a file define: a pupil's function in place of the reference
    // (exercises/manifest.tsv, exercise/manifest.cpp).
    {"RAYLAB_EXERCISE_RAY_SPHERE", "exercise/manifest.cpp"},
    {"RAYLAB_EXERCISE_RAY_TRIANGLE", "exercise/manifest.cpp"},
    {"RAYLAB_EXERCISE_SLAB_TEST", "exercise/manifest.cpp"},
    {"RAYLAB_EXERCISE_COSINE_HEMISPHERE", "exercise/manifest.cpp"},
    {"RAYLAB_EXERCISE_LAMBERT", "exercise/manifest.cpp"},
    {"RAYLAB_EXERCISE_GGX_D", "exercise/manifest.cpp"},
    {"RAYLAB_EXERCISE_SMITH_G", "exercise/manifest.cpp"},
    {"RAYLAB_EXERCISE_SCHLICK", "exercise/manifest.cpp"},
    {"RAYLAB_EXERCISE_THIN_LENS", "exercise/manifest.cpp"},
    {"RAYLAB_EXERCISE_RUNNING_MEAN", "exercise/manifest.cpp"},
    {"RAYLAB_INJECT_NONFINITE", "tests only (render/path_tracer_test.cpp)"},
    {"RAYLAB_LEAVE_OUT_ESCAPED", "tests only (render/accel_render_test.cpp)"},
};

// `name`, checked at compile time against kTracerDefines.
consteval const char* tracerDefine(const char* name) {
    for (const TracerDefine& d : kTracerDefines)
        if (d.name == std::string_view(name)) return name;
    throw "tracerDefine: not in kTracerDefines (render/tracer_defines.h)";
}

} // namespace raylab
