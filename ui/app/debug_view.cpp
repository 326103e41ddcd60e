#include "app/debug_view.h"

namespace raylab::ui {

std::string_view debugViewName(DebugView view) {
    switch (view) {
    case DebugView::Beauty: return "beauty";
    case DebugView::Normals: return "normals";
    case DebugView::Albedo: return "albedo";
    case DebugView::Depth: return "depth";
    case DebugView::MaterialId: return "material-id";
    case DebugView::ObjectId: return "object-id";
    case DebugView::NonFinite: return "nan";
    case DebugView::Noise: return "noise";
    case DebugView::BounceK: return "bounce";
    case DebugView::Direct: return "direct";
    case DebugView::Indirect: return "indirect";
    case DebugView::Boxes: return "boxes";
    case DebugView::Triangles: return "triangles";
    case DebugView::Uv: return "uv";
    }
    return "?";
}

std::optional<DebugView> parseDebugView(std::string_view name) {
    for (DebugView v : kDebugViews)
        if (debugViewName(v) == name) return v;
    return std::nullopt;
}

} // namespace raylab::ui
