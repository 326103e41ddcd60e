#include "app/viewport_click.h"

#include <string>

namespace raylab::ui {

void viewportClick(Viewer& viewer, UiState& ui, float x, float y) {
    const ImageRect& r = ui.image;
    if (!r.valid() || x < r.x || y < r.y || x >= r.x + r.width || y >= r.y + r.height) {
        viewer.log().info("click at (" + std::to_string(int(x)) + ", " + std::to_string(int(y)) + ") is outside the image");
        return;
    }
    const float ix = (x - r.x) / r.width * float(viewer.imageWidth());
    const float iy = (y - r.y) / r.height * float(viewer.imageHeight());
    if (ui.focusOnClick) {   // click-to-focus armed (Camera panel): focus once, then pick again
        ui.focusOnClick = false;
        viewer.focusAt(ix, iy);
        return;
    }
    if (viewer.inspection.clickInspects) {   // inspect mode (Inspector panel)
        viewer.inspection.inspect(viewer, int(ix), int(iy));
        return;
    }
    viewer.pick(ix, iy);
}

} // namespace raylab::ui
