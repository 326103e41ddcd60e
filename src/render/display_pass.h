#pragma once
// The display pass: a path tracer's accumulated image (or a debug view of it) to an RGBA8 texture
// through exposure, the tone map and the view's colouring (shaders/entry/display.frag). The viewer
// and the split screen draw with it; files take the same tone map on the CPU (io/image_io.h).
// Needs a current GL 4.5 context.
#include "gl/shader_program.h"
#include "io/image_io.h"
#include "render/debug_views.h"
#include "shaders/include/display_params.glsl"

namespace raylab {

using DisplayParams = glsl::DisplayParams;
static_assert(sizeof(DisplayParams) == 48, "std140 size of DisplayParams (shaders/include/display_params.glsl)");

// Parameters that show a width × height image of `view` through `transform`; the view's scales
// and the moments are the caller's to fill in.
DisplayParams displayParams(int width, int height, DebugView view, const DisplayTransform& transform);

class DisplayPass {
public:
    DisplayPass();
    ~DisplayPass();
    DisplayPass(const DisplayPass&) = delete;
    DisplayPass& operator=(const DisplayPass&) = delete;

    // Compiles the display shader anew; on a ShaderError the previous program stays.
    void reload();
    // Draws `accumulation` (RGBA32F, bottom row first, as PathTracer keeps it) into the pass's
    // texture, sized to params.imageSize; `moments` is the buffer the noise and NaN views read when
    // params.hasMoments. Compiles the shader on first use. Returns the texture.
    unsigned draw(unsigned accumulation, const DisplayParams& params, unsigned moments = 0);
    unsigned texture() const { return texture_; }   // RGBA8, linear minification; 0 before a draw
    int width() const { return width_; }
    int height() const { return height_; }

private:
    void ensureTarget(int width, int height);

    ShaderProgram program_;
    bool compiled_ = false;
    unsigned texture_ = 0;
    unsigned framebuffer_ = 0;
    unsigned vertexArray_ = 0;
    unsigned paramsBuffer_ = 0;
    int width_ = 0;
    int height_ = 0;
};

} // namespace raylab
