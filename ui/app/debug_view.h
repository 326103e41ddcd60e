#pragma once
// The viewer's debug views; the numbers are the shaders' (shaders/include/debug_views.glsl traces
// views 1-4, shaders/entry/display.frag draws all of them).
#include <optional>
#include <string_view>

namespace raylab::ui {

enum class DebugView {
    Beauty = 0, Normals = 1, Albedo = 2, Depth = 3, MaterialId = 4, NonFinite = 5, Noise = 6,
    BounceK = 7,    // radiance that reached the eye after exactly k bounces (Viewer::debugBounce)
    Direct = 8,     // bounces 0 and 1: emitters and sky seen directly, plus direct lighting
    Indirect = 9,   // bounces 2 and more
    Boxes = 10,     // BVH box tests of the camera ray (heat map; the tracer counts them)
    Triangles = 11, // triangle tests of the camera ray (heat map)
    Uv = 12,        // texture coordinates: (fract u, fract v, 0)
    ObjectId = 13,  // a colour per object (app/scene_object.h numbering: spheres, then meshes)
};

inline constexpr DebugView kDebugViews[] = {DebugView::Beauty,    DebugView::Normals,  DebugView::Albedo,
                                            DebugView::Depth,     DebugView::MaterialId, DebugView::ObjectId,
                                            DebugView::NonFinite,
                                            DebugView::Noise,     DebugView::BounceK,  DebugView::Direct,
                                            DebugView::Indirect, DebugView::Boxes,  DebugView::Triangles,
                                            DebugView::Uv};

// Script and UI names: beauty, normals, albedo, depth, material-id, object-id, nan, noise, bounce,
// direct, indirect, boxes, triangles, uv.
std::string_view debugViewName(DebugView view);
std::optional<DebugView> parseDebugView(std::string_view name);
// Views 1-4 and 7-13 are traced instead of the beauty path; 5-6 are drawn from the beauty path's
// moments.
inline bool tracedDebugView(DebugView v) { return (int(v) >= 1 && int(v) <= 4) || int(v) >= 7; }
// The heat maps: traced by a variant that counts traversal (RAYLAB_COUNT_TRAVERSAL); both store
// the box and the triangle count, so switching between them only redraws.
inline bool heatMapView(DebugView v) { return v == DebugView::Boxes || v == DebugView::Triangles; }

} // namespace raylab::ui
