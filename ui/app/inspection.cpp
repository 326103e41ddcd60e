#include "app/inspection.h"

#include "app/viewer.h"
#include "inspect/path_export.h"

#include <algorithm>

namespace raylab::ui {

void Inspection::clear() {
    paths_.clear();
    x_ = y_ = -1;
}

bool Inspection::inspect(Viewer& viewer, int x, int y) {
    if (!viewer.hasScene()) return false;
    const int w = viewer.imageWidth(), h = viewer.imageHeight();
    if (x < 0 || y < 0 || x >= w || y >= h) {
        viewer.log().error("inspect: pixel (" + std::to_string(x) + ", " + std::to_string(y) + ") is outside the " +
                           std::to_string(w) + "×" + std::to_string(h) + " image");
        return false;
    }
    try {
        if (!inspector_ || inspector_->extraDefines() != viewer.runningTracerDefines())
            inspector_ = std::make_unique<PathInspector>(PathInspector::kDefaultMaxRecords, viewer.runningTracerDefines());
        inspector_->setScene(viewer.tracedScene());
        inspector_->setBounceFilter(bounceFilterFor(viewer.debugView()), viewer.debugBounce());
        pathCount = std::clamp(pathCount, 1, 256);
        paths_ = inspector_->record(x, y, pathCount, viewer.tracer()->samplesPerPixel());
    } catch (const std::exception& e) {
        viewer.log().error(std::string("inspect: ") + e.what());
        return false;
    }
    x_ = x;
    y_ = y;
    filter_ = inspector_->bounceFilter();
    filterBounce_ = inspector_->filterBounce();
    panelOpen = true;
    shownPath = std::min(shownPath, int(paths_.size()) - 1);
    recordedAtRestart_ = viewer.stats().restarts;
    std::size_t bounces = 0;
    for (const PathRecord& p : paths_) bounces += p.bounces.size();
    viewer.log().info("inspected pixel (" + std::to_string(x) + ", " + std::to_string(y) + "): " +
                      std::to_string(paths_.size()) + " paths, " + std::to_string(bounces) + " bounce records");
    return true;
}

void Inspection::update(Viewer& viewer) {
    const std::uint64_t restarts = viewer.stats().restarts;
    const bool settled = restarts == lastSeenRestart_;   // not while the camera is being dragged
    lastSeenRestart_ = restarts;
    if (!follow || !active() || !viewer.hasScene() || restarts == recordedAtRestart_ || !settled) return;
    if (x_ >= viewer.imageWidth() || y_ >= viewer.imageHeight()) {
        clear();
        return;
    }
    inspect(viewer, x_, y_);
}

bool Inspection::exportPaths(Viewer& viewer, const std::filesystem::path& file) const {
    try {
        writePaths(file, paths_);
    } catch (const std::exception& e) {
        viewer.log().error(e.what());
        return false;
    }
    viewer.log().info("wrote " + std::to_string(paths_.size()) + " paths to " + file.string());
    return true;
}

// The shader takes the filter as a debug view number (debug_views.glsl).
static_assert(int(BounceFilter::Only) == int(DebugView::BounceK) && int(BounceFilter::Direct) == int(DebugView::Direct) &&
              int(BounceFilter::Indirect) == int(DebugView::Indirect) && int(BounceFilter::All) == int(DebugView::Beauty));

BounceFilter bounceFilterFor(DebugView view) {
    switch (view) {
    case DebugView::BounceK: return BounceFilter::Only;
    case DebugView::Direct: return BounceFilter::Direct;
    case DebugView::Indirect: return BounceFilter::Indirect;
    default: return BounceFilter::All;
    }
}

PathOverlay pathOverlay(const Scene& scene, int width, int height, const std::vector<PathRecord>& paths,
                        const PathOverlaySettings& settings, int path) {
    PathOverlay out;
    const auto line = [&](glm::vec3 a, glm::vec3 b, PathLineKind kind, int i) {
        if (auto s = projectSegment(scene, width, height, a, b)) out.lines.push_back({*s, kind, i});
    };
    for (int i = 0; i < int(paths.size()); ++i) {
        if (path >= 0 && i != path) continue;
        for (int k = 0; k < int(paths[std::size_t(i)].bounces.size()); ++k) {
            const BounceRecord& b = paths[std::size_t(i)].bounces[std::size_t(k)];
            // Lengths of the direction marks: a fraction of the distance to the eye, so they look
            // alike near and far; escaping rays run far past the scene.
            const float eye = glm::length(b.origin - scene.camera.position) + glm::length(b.position - scene.camera.position);
            const float mark = 0.12f * glm::length(b.position - scene.camera.position);
            if (!b.hit) {
                line(b.origin, b.origin + b.direction * (10.0f * eye + 10.0f), PathLineKind::Escape, i);
                continue;
            }
            line(b.origin, b.position, PathLineKind::Segment, i);
            if (auto p = projectPoint(scene, width, height, b.position)) out.hits.push_back({*p, i, k});
            if (settings.normals) line(b.position, b.position + b.normal * mark, PathLineKind::Normal, i);
            if (settings.sampled && b.sampled && b.lobe > 0)
                line(b.position, b.position + b.sampledDirection * mark, PathLineKind::Sampled, i);
            if (settings.shadowRays && (b.lightStatus == LightStatus::Visible || b.lightStatus == LightStatus::Occluded))
                line(b.position, b.shadowTarget(10.0f * eye + 10.0f),
                     b.lightStatus == LightStatus::Visible ? PathLineKind::ShadowVisible : PathLineKind::ShadowBlocked, i);
        }
    }
    return out;
}

} // namespace raylab::ui
