#pragma once
// The viewer's pixel path inspector (model of the Inspector panel): the inspected pixel, its
// recorded sample paths (src/inspect/path_inspector.h: the next samples the tracer will take
// there), which of them to show, and the paths as image-space lines for the overlay, drawn with
// the tracer's own camera (app/view_geometry.h). The values are those of the pixel on screen under
// the beauty view and the bounce views (bounce k, direct, indirect: the same bounce filter); the
// other debug views do not trace paths, so under them the beauty estimator is recorded. No ImGui here.
#include "app/debug_view.h"
#include "app/view_geometry.h"
#include "inspect/path_inspector.h"
#include "inspect/path_record.h"
#include "scene/scene.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

namespace raylab::ui {

class Viewer;

struct PathOverlaySettings {
    bool show = true;
    bool normals = true;        // geometric normals at the hits
    bool sampled = true;        // the BSDF's sampled directions
    bool shadowRays = true;     // next-event estimation's rays to the lights
};

enum class PathLineKind { Segment, Escape, Normal, Sampled, ShadowVisible, ShadowBlocked };

struct PathLine {
    Segment segment;
    PathLineKind kind = PathLineKind::Segment;
    int path = 0;
};
struct PathDot {
    ImagePoint point;
    int path = 0;
    int bounce = 0;
};
struct PathOverlay {
    std::vector<PathLine> lines;
    std::vector<PathDot> hits;
};

class Inspection {
public:
    bool panelOpen = false;       // the Inspector panel is shown
    bool clickInspects = false;   // inspect mode: viewport clicks inspect instead of picking
    bool follow = true;           // record again when the image restarts (camera, settings)
    int pathCount = 8;            // paths recorded per inspection (1 to 256)
    int shownPath = -1;           // -1: all paths in the overlay; else one
    int tableBounce = 0;          // the bounce the BRDF explorer takes its direction from
    PathOverlaySettings overlay;

    bool active() const { return x_ >= 0; }
    int x() const { return x_; }
    int y() const { return y_; }
    const std::vector<PathRecord>& paths() const { return paths_; }
    // The bounce view the paths were recorded under (All: the beauty estimator).
    BounceFilter filter() const { return filter_; }
    int filterBounce() const { return filterBounce_; }
    void clear();
    // Records the next pathCount samples of image pixel (x, y) of the viewer's traced image.
    // Logs and returns false for a pixel outside the image or a GL/shader error.
    bool inspect(Viewer& viewer, int x, int y);
    // Once a frame: records again after a restart when following (once the restarts settle: a
    // camera drag restarts every frame, and each recording uploads the scene).
    void update(Viewer& viewer);
    bool exportPaths(Viewer& viewer, const std::filesystem::path& file) const;

private:
    std::unique_ptr<PathInspector> inspector_;
    std::vector<PathRecord> paths_;
    int x_ = -1;
    int y_ = -1;
    BounceFilter filter_ = BounceFilter::All;
    int filterBounce_ = 0;
    std::uint64_t recordedAtRestart_ = 0;
    std::uint64_t lastSeenRestart_ = 0;
};

// The bounce filter of a debug view: its own for the bounce views, All (beauty) for the others.
BounceFilter bounceFilterFor(DebugView view);

// The recorded paths as image lines of a width × height image (only `path` when >= 0).
PathOverlay pathOverlay(const Scene& scene, int width, int height, const std::vector<PathRecord>& paths,
                        const PathOverlaySettings& settings, int path = -1);

} // namespace raylab::ui
