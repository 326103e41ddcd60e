#pragma once
// One ImGui widget for one parameter-table entry (scene/parameters.h): a drag for numbers with the
// table's range, a colour editor for reflectances, a combo for enums, the help, unit, range and
// trigger as a tooltip. Panels build their widgets from the table, so new keys appear by themselves.
#include "scene/scene_keys.h"
#include "app/viewer.h"

namespace raylab::ui {

// Draws the widget for `param` and applies an edit through the viewer (which restarts or reloads
// as the key's trigger says). Returns true when the value changed. vec3 drags move by
// `vectorSpeed` per pixel (positions: a fraction of the scene's size suits millimetre scenes too).
bool paramWidget(Viewer& viewer, const SceneParam& param, float vectorSpeed = 0.01f);

} // namespace raylab::ui
