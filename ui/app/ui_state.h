#pragma once
// What the views share besides the Viewer model: text boxes, requests that the window loop carries
// out (a screenshot needs the finished frame), and where the viewport drew the image last frame.
#include <string>

namespace raylab::ui {

struct ImageRect {
    float x = 0.0f;   // window pixels, top-left of the shown image
    float y = 0.0f;
    float width = 0.0f;
    float height = 0.0f;
    bool valid() const { return width > 0.0f && height > 0.0f; }
};

struct UiState {
    std::string openPath;          // the path box of the Render panel
    std::string savePath;          // where "Save scene" writes
    std::string screenshotPath = "raylab-screenshot.png";
    std::string exportPath = "raylab-render.exr";
    std::string pendingScreenshot; // set by a button, key or script; done after the frame is drawn
    bool pixelTooltip = true;      // value under the cursor
    bool focusOnClick = false;     // click-to-focus armed (Camera panel): the next click focuses
    ImageRect image;               // where the viewport drew the traced image
    bool dragging = false;         // a mouse drag in the viewport is moving the camera
};

} // namespace raylab::ui
