// The viewport: the traced image fitted into its window, overlays on top, the error banner, the
// value under the cursor, and the mouse and key camera controls.
#include "panels/panels.h"

#include "app/bvh_overlay.h"
#include "app/camera_control.h"
#include "app/light_gizmo.h"
#include "app/scene_object.h"
#include "panels/heat_legend.h"
#include "app/view_geometry.h"
#include "script/key_actions.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

namespace raylab::ui {
namespace {

constexpr float kRadiansPerPixel = 0.005f;
constexpr float kTurnSpeed = 1.2f;   // radians per second for the arrow keys

ImVec2 toWindow(const ImageRect& r, int w, int h, ImagePoint p) {
    return ImVec2(r.x + p.x / float(w) * r.width, r.y + p.y / float(h) * r.height);
}

void drawOverlays(Viewer& viewer, const ImageRect& r) {
    const Scene& scene = viewer.scene();
    const OverlaySettings& o = viewer.overlays;
    if (!o.boxes && !o.selectedOnly && !o.bvh && !o.meshBvh && !o.lights) return;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    dl->PushClipRect(ImVec2(r.x, r.y), ImVec2(r.x + r.width, r.y + r.height), true);
    const int w = viewer.imageWidth(), h = viewer.imageHeight();
    if (const SceneGeometry* g = viewer.geometry()) {
        if (o.meshBvh)
            for (const Segment& s : meshBvhSegments(scene, *g, w, h, o.bvhDepth))
                dl->AddLine(toWindow(r, w, h, s.a), toWindow(r, w, h, s.b), IM_COL32(255, 140, 0, 255), 1.0f);
        if (o.bvh)
            for (const Segment& s : topLevelBvhSegments(scene, *g, w, h, o.bvhDepth))
                dl->AddLine(toWindow(r, w, h, s.a), toWindow(r, w, h, s.b), IM_COL32(255, 0, 255, 255), 1.0f);
    }
    const SceneGeometry* g = viewer.geometry();
    for (int i = 0; g && i < objectCount(scene) && (o.boxes || o.selectedOnly); ++i) {   // spheres, then meshes
        const bool sel = i == viewer.selection.object();
        if (viewer.overlays.selectedOnly && !sel) continue;
        const ImU32 colour = sel ? IM_COL32(0, 255, 255, 255) : IM_COL32(255, 255, 0, 255);
        const std::optional<Box> box = objectBounds(scene, *g, i);
        if (!box) continue;
        for (const Segment& s : projectBox(scene, w, h, *box))
            dl->AddLine(toWindow(r, w, h, s.a), toWindow(r, w, h, s.b), colour, 1.0f);
    }
    for (int i = 0; o.lights && i < int(scene.lights.size()); ++i) {
        const ImU32 colour = i == viewer.selection.light() ? IM_COL32(0, 255, 255, 255) : IM_COL32(255, 230, 90, 255);
        for (const Segment& s : lightGizmo(scene, w, h, i))
            dl->AddLine(toWindow(r, w, h, s.a), toWindow(r, w, h, s.b), colour, 1.0f);
    }
    dl->PopClipRect();
}

void keyboardCamera(Viewer& viewer) {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.WantTextInput || io.KeyCtrl) return;
    const float dt = std::min(io.DeltaTime, 0.1f);
    const float step = viewer.cameraSpeed * dt * (io.KeyShift ? 4.0f : 1.0f);
    // The backend indexes KeysDown by GLFW key codes (script/key_actions.h).
    auto down = [](CameraMotion m) {
        const int key = cameraKey(m);
        return key >= 0 && key < int(IM_ARRAYSIZE(ImGui::GetIO().KeysDown)) && ImGui::IsKeyDown(key);
    };
    auto axis = [&down](CameraMotion plus, CameraMotion minus) { return float(down(plus)) - float(down(minus)); };
    const float forward = axis(CameraMotion::Forward, CameraMotion::Back);
    const float right = axis(CameraMotion::Right, CameraMotion::Left);
    const float up = axis(CameraMotion::Up, CameraMotion::Down);
    const float yaw = axis(CameraMotion::TurnRight, CameraMotion::TurnLeft);
    const float pitch = axis(CameraMotion::LookUp, CameraMotion::LookDown);
    if (forward == 0.0f && right == 0.0f && up == 0.0f && yaw == 0.0f && pitch == 0.0f) return;
    Camera& cam = viewer.scene().camera;
    moveCamera(cam, forward * step, right * step, up * step);
    turnCamera(cam, yaw * kTurnSpeed * dt, pitch * kTurnSpeed * dt);
    viewer.document().changed(Trigger::ResetAccumulation);
}

void tooltip(Viewer& viewer, const ImageRect& r) {
    const ImVec2 m = ImGui::GetIO().MousePos;
    const float fx = (m.x - r.x) / r.width * float(viewer.imageWidth());
    const float fy = (m.y - r.y) / r.height * float(viewer.imageHeight());
    const int x = int(fx), y = int(fy);
    if (x < 0 || y < 0 || x >= viewer.imageWidth() || y >= viewer.imageHeight()) return;
    const glm::vec4 v = viewer.pixelValue(x, y);
    const Scene& scene = viewer.scene();
    const std::optional<ViewHit> hit = viewHit(scene, *viewer.geometry(), viewer.imageWidth(), viewer.imageHeight(), ImagePoint{fx, fy});
    ImGui::BeginTooltip();
    ImGui::Text("pixel (%d, %d)", x, y);
    if (heatMapView(viewer.debugView()))
        ImGui::Text("camera ray: %.4g box tests, %.4g triangle tests (mean over the pixel's samples)", double(v.x), double(v.y));
    else if (viewer.debugView() == DebugView::Samples && viewer.tracer())
        ImGui::Text("samples: %llu", static_cast<unsigned long long>(viewer.tracer()->samplesAt(x, y)));
    else if (viewer.debugView() == DebugView::Uv)
        ImGui::Text("uv (fractional part): %.4f %.4f", double(v.x), double(v.y));
    else
        ImGui::Text("%s: %.4g %.4g %.4g", std::string(debugViewName(viewer.debugView())).c_str(), double(v.x), double(v.y), double(v.z));
    if (hit) {
        const ObjectRef o = *objectRef(scene, hit->object);
        ImGui::Text("object %d (%s %d), material %d '%s'", hit->object, o.mesh ? "mesh" : "sphere", o.index, hit->material,
                    scene.materials[std::size_t(hit->material)].name.c_str());
        if (const std::optional<Box> b = objectBounds(scene, *viewer.geometry(), hit->object))
            ImGui::Text("bounds [%.4g, %.4g, %.4g] .. [%.4g, %.4g, %.4g]", double(b->lo.x), double(b->lo.y), double(b->lo.z),
                        double(b->hi.x), double(b->hi.y), double(b->hi.z));
    } else {
        ImGui::TextUnformatted("sky");
    }
    ImGui::EndTooltip();
}

} // namespace

void drawViewport(Viewer& viewer, UiState& ui) {
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(2, 2));
    if (ui.focusViewport) ImGui::SetNextWindowFocus();
    ui.focusViewport = false;
    const bool open = ImGui::Begin("Viewport", nullptr, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse);
    ImGui::PopStyleVar();
    if (!open) {
        ImGui::End();
        return;
    }
    if (!viewer.document().lastError().empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.35f, 0.3f, 1.0f));
        ImGui::TextWrapped("%s", viewer.document().lastError().c_str());
        ImGui::PopStyleColor();
    }
    const unsigned texture = viewer.displayTexture();
    if (!texture) {
        ui.image = {};
        ImGui::TextUnformatted("No scene. Open one in the Render panel or drop a file here.");
        ImGui::End();
        return;
    }
    // Fit the image into the space left, keeping its aspect ratio, centred.
    const ImVec2 avail = ImGui::GetContentRegionAvail();
    const float aspect = float(viewer.imageWidth()) / float(viewer.imageHeight());
    float w = avail.x, h = avail.x / aspect;
    if (h > avail.y) {
        h = avail.y;
        w = h * aspect;
    }
    w = std::max(w, 1.0f);
    h = std::max(h, 1.0f);
    ImVec2 pos = ImGui::GetCursorScreenPos();
    pos.x += std::max(0.0f, (avail.x - w) * 0.5f);
    pos.y += std::max(0.0f, (avail.y - h) * 0.5f);
    ImGui::SetCursorScreenPos(pos);
    ui.image = ImageRect{pos.x, pos.y, w, h};
    ImGui::InvisibleButton("##image", ImVec2(w, h), ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
    // GL textures start at the bottom row: flip v.
    ImGui::GetWindowDrawList()->AddImage(ImTextureID(std::uintptr_t(texture)), pos, ImVec2(pos.x + w, pos.y + h),
                                         ImVec2(0, 1), ImVec2(1, 0));
    drawSplitView(ui, ui.image);   // classroom: A | B over the image
    drawOverlays(viewer, ui.image);
    drawPathOverlay(viewer, ui.image);
    if (heatMapView(viewer.debugView())) {   // the heat map's scale, on the image's bottom-left
        const std::string hi = std::to_string(int(std::lround(viewer.heatScaleInUse()))) +
                               (viewer.debugView() == DebugView::Boxes ? " box tests" : " triangle tests");
        const float bw = std::min(160.0f, w * 0.4f), th = ImGui::GetTextLineHeight();
        ImDrawList* dl = ImGui::GetWindowDrawList();
        const ImVec2 at(pos.x + 6.0f, pos.y + h - 14.0f - th);
        dl->AddRectFilled(ImVec2(at.x - 3.0f, at.y - 3.0f), ImVec2(at.x + bw + 3.0f, at.y + 10.0f + th + 3.0f), IM_COL32(0, 0, 0, 160));
        drawHeatLegend(dl, at, bw, 8.0f, "0", hi.c_str());
    }

    const ImGuiIO& io = ImGui::GetIO();
    Camera& cam = viewer.scene().camera;
    if (ImGui::IsItemActive() && !ui.draggingDivider && (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 3.0f) || ImGui::IsMouseDragging(ImGuiMouseButton_Right, 3.0f))) {
        ui.dragging = true;
        if (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f) {
            if (io.MouseDown[0]) orbitCamera(cam, io.MouseDelta.x * kRadiansPerPixel, io.MouseDelta.y * kRadiansPerPixel);
            else turnCamera(cam, io.MouseDelta.x * kRadiansPerPixel, -io.MouseDelta.y * kRadiansPerPixel);
            viewer.document().changed(Trigger::ResetAccumulation);
        }
    }
    if (ImGui::IsItemDeactivated()) {
        if (!ui.dragging && !ui.draggingDivider && ImGui::IsMouseReleased(ImGuiMouseButton_Left)) viewportClick(viewer, ui, io.MousePos.x, io.MousePos.y);
        ui.dragging = false;
    }
    if (ImGui::IsItemHovered()) {
        if (io.MouseWheel != 0.0f) {
            dollyCamera(cam, io.MouseWheel > 0 ? 0.9f : 1.0f / 0.9f);
            viewer.document().changed(Trigger::ResetAccumulation);
        }
        if (ui.pixelTooltip && !ui.dragging) tooltip(viewer, ui.image);
    }
    if (ImGui::IsWindowFocused()) keyboardCamera(viewer);
    ImGui::End();
}

} // namespace raylab::ui
