#pragma once
// A left click at a window pixel, as the viewport and the automation script deliver it: when it
// lands on the shown image, the object under it is picked (the image may be scaled in the window),
// or, with click-to-focus armed (UiState::focusOnClick), the camera focuses there and the mode ends;
// or in inspect mode its pixel is inspected (app/inspection.h).
#include "app/ui_state.h"
#include "app/viewer.h"

namespace raylab::ui {

void viewportClick(Viewer& viewer, UiState& ui, float x, float y);

} // namespace raylab::ui
