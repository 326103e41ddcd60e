#pragma once
// Every #define the host can set on the path tracer's entry points, in one list. The tracer's
// fragment entry (shaders/entry/trace.frag, compiled with entry/fullscreen.vert, which receives
// the same defines and uses none) and its compute entry (entry/trace.comp) each name, in their
// header comment, every define they can receive (tests/render/tracer_defines_test.cpp checks it).
// Host code names a define through tracerDefine("NAME"), which does not compile for a name that is
// missing here, so a new define cannot bypass the list.
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
    {"RAYLAB_FEATURE_SPHERES", "render/shader_variant.cpp"},
    {"RAYLAB_FEATURE_MESHES", "render/shader_variant.cpp"},
    {"RAYLAB_FEATURE_SMOOTH_NORMALS", "render/shader_variant.cpp"},
    {"RAYLAB_FEATURE_DOF", "render/shader_variant.cpp"},
    {"RAYLAB_FEATURE_TEXTURES", "render/shader_variant.cpp"},
    {"RAYLAB_TOP_LEVEL_LINEAR", "render/shader_variant.cpp"},
    {"RAYLAB_SHOW_MIP_LEVEL", "render/shader_variant.cpp"},
    {"RAYLAB_NEE", "render/shader_variant.cpp"},
    {"RAYLAB_GENERAL_BSDF", "render/shader_variant.cpp"},
    {"RAYLAB_SKY_MAP", "render/shader_variant.cpp"},
    {"RAYLAB_TEXTURE_ROUGHNESS", "render/shader_variant.cpp"},
    {"RAYLAB_TEXTURE_METALLIC", "render/shader_variant.cpp"},
    {"RAYLAB_TEXTURE_EMISSION", "render/shader_variant.cpp"},
    {"RAYLAB_TEXTURE_WRAP_MODES", "render/shader_variant.cpp"},
    {"RAYLAB_STAGE", "render/shader_variant.cpp"},
    {"RAYLAB_EMISSIVE_TRIANGLES", "render/shader_variant.cpp"},
    {"RAYLAB_LIGHT_POWER_SELECTION", "render/shader_variant.cpp"},
    // The compute entry's work-group size (render/path_tracer.cpp).
    {"LOCAL_SIZE_X", "render/path_tracer.cpp", true},
    {"LOCAL_SIZE_Y", "render/path_tracer.cpp", true},
    // Debug variants (TracerOptions::extraDefines).
    {"RAYLAB_DEBUG_VIEWS", "render/tracer_variants.cpp"},
    {"RAYLAB_DEBUG_MOMENTS", "render/tracer_variants.cpp"},
    {"RAYLAB_COUNT_TRAVERSAL", "render/tracer_variants.cpp"},
    {"RAYLAB_INSPECT_PATHS", "inspect/path_inspector.cpp"},
    {"RAYLAB_INJECT_NONFINITE", "tests only (render/path_tracer_test.cpp)"},
};

// `name`, checked at compile time against kTracerDefines.
consteval const char* tracerDefine(const char* name) {
    for (const TracerDefine& d : kTracerDefines)
        if (d.name == std::string_view(name)) return name;
    throw "tracerDefine: not in kTracerDefines (render/tracer_defines.h)";
}

} // namespace raylab
