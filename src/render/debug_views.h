#pragma once
// The debug views as the host sees them, expanded from the one list both sides share
// (shaders/include/debug_view_table.glsl): the ids the shader tests, the names the script, the
// panel and raylab-render take, and what each view needs of the tracer and the display pass.
#include "shaders/include/debug_view_table.glsl"

#include <array>
#include <optional>
#include <string_view>

namespace raylab {

enum class DebugView {
#define RAYLAB_DEBUG_VIEW_ENUM(id, NAME, Name, name, traced, moments, counts, display, legend) Name = id,
    RAYLAB_DEBUG_VIEW_TABLE(RAYLAB_DEBUG_VIEW_ENUM)
#undef RAYLAB_DEBUG_VIEW_ENUM
};

struct DebugViewInfo {
    DebugView view;
    std::string_view name;
    bool traced;            // traced in place of the beauty path (RAYLAB_DEBUG_VIEWS)
    bool moments;           // drawn from the beauty path's moments (RAYLAB_DEBUG_MOMENTS)
    bool countsTraversal;   // RAYLAB_COUNT_TRAVERSAL and the heat-max buffer
    int display;            // DEBUG_DISPLAY_*
    std::string_view legend;
};

inline constexpr DebugViewInfo kDebugViewTable[] = {
#define RAYLAB_DEBUG_VIEW_INFO(id, NAME, Name, name, traced, moments, counts, display, legend) \
    {DebugView::Name, name, traced != 0, moments != 0, counts != 0, display, legend},
    RAYLAB_DEBUG_VIEW_TABLE(RAYLAB_DEBUG_VIEW_INFO)
#undef RAYLAB_DEBUG_VIEW_INFO
};

// Mesa's GLSL preprocessor splits a string literal with an escape at its commas
// (debug_view_table.glsl): no character here may need one.
constexpr bool needsNoEscape(std::string_view text) {
    for (const char c : text)
        if (c == '\\' || c == '"' || static_cast<unsigned char>(c) < 0x20) return false;
    return true;
}
static_assert([] {
    for (const DebugViewInfo& v : kDebugViewTable)
        if (!needsNoEscape(v.name) || !needsNoEscape(v.legend)) return false;
    return true;
}(), "an escape (\\n, \\\", \\\\) in a debug view's name or legend (shaders/include/debug_view_table.glsl)");

// Every view in table order (the order the panel and the script list them).
inline constexpr auto kDebugViews = [] {
    std::array<DebugView, std::size(kDebugViewTable)> views{};
    for (std::size_t i = 0; i < views.size(); ++i) views[i] = kDebugViewTable[i].view;
    return views;
}();

constexpr const DebugViewInfo& debugViewInfo(DebugView view) {
    for (const DebugViewInfo& v : kDebugViewTable)
        if (v.view == view) return v;
    return kDebugViewTable[0];
}

constexpr std::string_view debugViewName(DebugView view) { return debugViewInfo(view).name; }

constexpr std::optional<DebugView> parseDebugView(std::string_view name) {
    for (const DebugViewInfo& v : kDebugViewTable)
        if (v.name == name) return v.view;
    return std::nullopt;
}

// Traced instead of the beauty path.
constexpr bool tracedDebugView(DebugView view) { return debugViewInfo(view).traced; }
// The heat maps: both store the box and the triangle count, so switching between them only redraws.
constexpr bool heatMapView(DebugView view) { return debugViewInfo(view).countsTraversal; }

} // namespace raylab
