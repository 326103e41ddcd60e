// Material panel: the outliner (every object: spheres, then mesh instances, then the lights; click
// to select), the selected object's keys (a sphere's centre and radius, a mesh's transform and displacement) and the
// keys of the material it edits, or the selected light's keys (light_panel.cpp), all built from
// the parameter tables so new keys show up without UI changes. A mesh with glTF per-triangle
// materials lists them; the one under the last click is edited.
#include "panels/panels.h"
#include "panels/param_widget.h"

#include "app/scene_light.h"
#include "app/scene_object.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <string>

namespace raylab::ui {
namespace {

// Drag speed for positions: a 500th of the scene's extent per pixel (the top-level BVH's root).
float positionSpeed(const Viewer& viewer) {
    const SceneGeometry* g = viewer.geometry();
    if (!g || g->topNodes.empty()) return 0.01f;
    const glm::vec3 extent = glm::vec3(g->topNodes[0].boundsMax) - glm::vec3(g->topNodes[0].boundsMin);
    return std::max(0.002f * std::max({extent.x, extent.y, extent.z}), 1e-4f);
}

// A mesh's displacement: each change tessellates and displaces it again (trigger "reload scene");
// the texture path applies on Enter. An edit replaces the scene, so `m` is read before any widget.
void displacementKeys(Viewer& viewer, const std::string& prefix, const Mesh& m) {
    if (!m.displacement.texture.empty())
        ImGui::TextDisabled("displaced: %zu -> %zu triangles in %.1f ms", m.displacement.trianglesBefore,
                            m.triangles.size(), m.displacement.milliseconds);
    char path[1024];
    std::snprintf(path, sizeof path, "%s", m.displacement.texture.c_str());
    if (ImGui::InputText("displacement_texture", path, sizeof path, ImGuiInputTextFlags_EnterReturnsTrue))
        viewer.document().set(prefix + "displacement_texture", path);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("displacement_texture: an image file, relative to the scene file (Enter applies)");
    for (const DisplacementParamSpec& p : displacementParameters())
        paramWidget(viewer, resolveParam(viewer.scene(), prefix + std::string(p.key)));
}

void objectKeys(Viewer& viewer, int sel, const ObjectRef& r) {
    const Scene& scene = viewer.scene();
    const std::string prefix = "objects." + std::to_string(sel) + ".";
    const float speed = positionSpeed(viewer);
    if (r.mesh) {
        const Mesh& m = scene.meshes[std::size_t(r.index)];
        ImGui::Text("object %d: mesh %d, %zu triangles", sel, r.index, m.triangles.size());
        if (!m.file.empty()) ImGui::TextDisabled("%s", m.file.c_str());
        // Moving a mesh rebuilds only the top-level BVH (trigger "move objects").
        for (const TransformParamSpec& p : transformParameters())
            paramWidget(viewer, resolveParam(scene, prefix + std::string(p.key)),
                        p.key == "transform.translation" ? speed : 0.01f);
        displacementKeys(viewer, prefix, viewer.scene().meshes[std::size_t(r.index)]);   // `m` is stale after an edit
    } else {
        ImGui::Text("object %d: sphere %d", sel, r.index);
        for (const SphereParamSpec& p : sphereParameters())
            paramWidget(viewer, resolveParam(scene, prefix + std::string(p.key)), speed);
        // A sphere's rotation shows nowhere and its scale must stay uniform (radius does that).
        paramWidget(viewer, resolveParam(scene, prefix + "transform.translation"), speed);
    }
}

// The object's own material: a combo over the scene's materials. A glTF mesh's triangles carry
// the file's materials instead: no combo.
void materialAssignment(Viewer& viewer, int sel, const ObjectRef& r) {
    Scene& scene = viewer.scene();
    if (r.mesh && !scene.meshes[std::size_t(r.index)].triangleMaterials.empty()) return;
    int& own = r.mesh ? scene.meshes[std::size_t(r.index)].material : scene.spheres[std::size_t(r.index)].material;
    if (!ImGui::BeginCombo("material", scene.materials[std::size_t(own)].name.c_str())) return;
    for (int j = 0; j < int(scene.materials.size()); ++j)
        if (ImGui::Selectable(scene.materials[std::size_t(j)].name.c_str(), j == own)) {
            own = j;
            viewer.selection.select(sel, j);
            viewer.document().changed(Trigger::ReloadScene);   // recompiles only if the feature set changed
            break;   // the scene's vectors were replaced: `own` is gone
        }
    ImGui::EndCombo();
}

} // namespace

void drawMaterialPanel(Viewer& viewer, UiState&) {
    if (!ImGui::Begin("Material")) {
        ImGui::End();
        return;
    }
    if (!viewer.hasScene()) {
        ImGui::End();
        return;
    }
    const Scene& scene = viewer.scene();
    ImGui::PushItemWidth(-80.0f);
    ImGui::TextDisabled("Click an object in the viewport or here.");
    if (ImGui::BeginListBox("##outliner", ImVec2(-1, 6 * ImGui::GetTextLineHeightWithSpacing()))) {
        static int scrolledTo = -1;   // a pick or a script's select scrolls its row into view once
        // One row per object, then one per light: the selection's row.
        const int objects = objectCount(scene);
        const int selRow = viewer.selection.light() >= 0 ? objects + viewer.selection.light() : viewer.selection.object();
        for (int i = 0; i < objects + int(scene.lights.size()); ++i) {
            const bool light = i >= objects;
            const std::string label = light ? lightLabel(scene, i - objects) : objectLabel(scene, i);
            if (ImGui::Selectable(label.c_str(), i == selRow)) {
                if (light) viewer.selection.selectLight(i - objects);
                else viewer.selection.select(i);
            }
            if (i == selRow && scrolledTo != i) ImGui::SetScrollHereY();
        }
        scrolledTo = selRow;
        ImGui::EndListBox();
    }
    if (viewer.selection.light() >= 0) {
        ImGui::Separator();
        drawLightKeys(viewer, positionSpeed(viewer));
    }
    const int sel = viewer.selection.object();
    if (const auto r = objectRef(scene, sel)) {
        ImGui::Separator();
        objectKeys(viewer, sel, *r);
        materialAssignment(viewer, sel, *r);
        const std::vector<int> materials = objectMaterials(viewer.scene(), sel);
        const int m = viewer.selection.editedMaterial();
        if (materials.size() > 1) {
            ImGui::TextDisabled("its materials (a click in the viewport picks the one there):");
            for (const int j : materials)
                if (ImGui::Selectable(("  " + viewer.scene().materials[std::size_t(j)].name).c_str(), j == m))
                    viewer.selection.select(sel, j);
        }
        ImGui::Separator();
        ImGui::TextWrapped("material '%s' (shared by every object that uses it)", viewer.scene().materials[std::size_t(m)].name.c_str());
        for (const MaterialParamSpec& p : materialParameters())
            paramWidget(viewer, resolveParam(viewer.scene(), "materials." + std::to_string(m) + "." + std::string(p.key)));
    }
    ImGui::PopItemWidth();
    ImGui::End();
}

} // namespace raylab::ui
