#pragma once
// The estimator's switchable stages as scene keys (shaders/include/estimator_stages.glsl): the one
// list the viewer's Estimator header, the EXR metadata and the Python module's metadata follow.
#include "scene/scene.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace raylab {

inline constexpr std::string_view kEstimatorStageKeys[] = {"render.diffuse_sampling", "render.ggx_sampling",
                                                           "render.light_selection", "render.light_sampling",
                                                           "render.accel"};

// Each stage of the scene as (name without "render.", value as the scene writes it):
// {"diffuse_sampling", "cosine"}, ...
std::vector<std::pair<std::string, std::string>> estimatorStages(const Scene& scene);

} // namespace raylab
