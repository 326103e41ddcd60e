// The Light section of the Material panel: the keys of the light selected in the outliner, those
// of its type (a point light's position and intensity or power, a spot's cone, a sun's direction,
// irradiance and angular radius), built from the parameter table. An edit goes through the scene
// document, which restarts the image and re-uploads the tracer's lights.
#include "panels/panels.h"
#include "panels/param_widget.h"

#include "app/scene_light.h"
#include "inspect/light_names.h"

#include <imgui.h>

#include <string>

namespace raylab::ui {

void drawLightKeys(Viewer& viewer, float positionSpeed) {
    const int i = viewer.selection.light();
    if (i < 0 || i >= int(viewer.scene().lights.size())) return;
    const Light& l = viewer.scene().lights[std::size_t(i)];
    ImGui::Text("%s", lightLabel(viewer.scene(), i).c_str());
    if (isDeltaLight(l)) ImGui::TextDisabled("a delta light: no ray can hit it, only light samples (render.nee) find it");
    if ((l.type == Light::Type::Point || l.type == Light::Type::Spot) && l.power > 0.0f)
        ImGui::TextDisabled("power is set: it replaces intensity (an intensity edit clears it)");
    for (const std::string& key : lightKeys(viewer.scene(), i))
        paramWidget(viewer, resolveParam(viewer.scene(), key), key.ends_with(".position") ? positionSpeed : 0.01f);
}

} // namespace raylab::ui
