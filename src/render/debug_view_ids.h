#pragma once
// The debug views the tracer itself computes (shaders/include/debug_views.glsl, compiled with
// RAYLAB_DEBUG_VIEWS): their names and uDebugView ids, shared by raylab-render's --debug-view and
// the viewer (ui/app/debug_view.h has the same ids; a test keeps the two in step).
#include <array>
#include <optional>
#include <string_view>

namespace raylab {

struct TracedDebugView {
    std::string_view name;
    int id;                 // uDebugView
    bool countsTraversal;   // needs RAYLAB_COUNT_TRAVERSAL and a buffer at binding 17
};

inline constexpr std::array<TracedDebugView, 8> kTracedDebugViews = {{
    {"normals", 1, false},
    {"albedo", 2, false},
    {"depth", 3, false},
    {"material-id", 4, false},
    {"object-id", 13, false},
    {"boxes", 10, true},
    {"triangles", 11, true},
    {"uv", 12, false},
}};

inline std::optional<TracedDebugView> findTracedDebugView(std::string_view name) {
    for (const TracedDebugView& v : kTracedDebugViews)
        if (v.name == name) return v;
    return std::nullopt;
}

} // namespace raylab
