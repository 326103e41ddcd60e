#pragma once
// The debug variants' buffers beside the path tracer: the per-pixel moments the noise and NaN views
// are drawn from, and the heat maps' largest count of one camera ray (shaders/include/
// debug_views.glsl). Needs a current GL 4.5 context.
#include "gl/shader_program.h"
#include "render/debug_views.h"

#include <glm/glm.hpp>

namespace raylab {

class DebugBuffers {
public:
    DebugBuffers();
    ~DebugBuffers();
    DebugBuffers(const DebugBuffers&) = delete;
    DebugBuffers& operator=(const DebugBuffers&) = delete;

    // Sizes the moments for a width × height image (none when either is 0) and clears them and
    // the heat maximum: call whenever accumulation restarts.
    void restart(int width, int height);
    // Binds both at BINDING_DEBUG_MOMENTS and BINDING_DEBUG_HEAT_MAX for the passes that follow.
    void bind() const;
    unsigned moments() const { return moments_; }   // vec4 per pixel, bottom row first; 0 for none
    // The largest box (x) and triangle (y) count of one camera ray since the restart.
    glm::uvec2 heatMax() const;

private:
    unsigned moments_ = 0;
    unsigned heatMax_ = 0;
};

// Selects what a RAYLAB_DEBUG_VIEWS program traces: `view`, and `bounce` for DebugView::BounceK.
// The program keeps it until set again (a new scene's program starts at the beauty view).
void setTracedView(const ShaderProgram& program, DebugView view, int bounce);

} // namespace raylab
