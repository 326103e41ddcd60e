#pragma once
// `expect WHAT VALUE` (script/script.h): the state a lesson step's text describes, checked where the
// line stands in the step, so a step cannot end on a state its text does not show.
#include "scene/scene.h"

#include <string>

namespace raylab {

// The viewer state lesson steps set that the scene does not hold.
struct ViewState {
    std::string debugView = "beauty";   // a name of shaders/include/debug_view_table.glsl
    double scale = -1.0;                // resolution scale; < 0 when not known (no `scale` yet)
    int bounceStep = 0;                 // bounce stepping's limit, 0 = off
};

// "" when the state has VALUE. WHAT is debug-view, scale or bounce-step (the view state), or a key
// of the parameter table (render.max_bounces, materials.ball.albedo, objects.1.radius). Otherwise
// what differs ("render.max_bounces is 1, expected 4") or why the line cannot be checked (an
// unknown key, a file key, a value the key does not accept).
std::string expectationFailure(const Scene& scene, const ViewState& view, const std::string& what,
                               const std::string& value);

} // namespace raylab
