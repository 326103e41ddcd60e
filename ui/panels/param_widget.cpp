#include "panels/param_widget.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace raylab::ui {
namespace {

float lowerOf(const ValueSpec& s, float fallback) { return s.min ? float(s.min->value) : fallback; }
float upperOf(const ValueSpec& s, float fallback) { return s.max ? float(s.max->value) : fallback; }

void tooltip(const ValueSpec& s) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::Text("%.*s", int(s.key.size()), s.key.data());
    ImGui::TextWrapped("%.*s", int(s.help.size()), s.help.data());
    const std::string range = describeRange(s);
    const std::string_view trig = triggerName(s.trigger);
    ImGui::TextDisabled("%.*s, range %s%s%.*s; a change: %.*s", int(typeName(s.type).size()), typeName(s.type).data(),
                        range.c_str(), s.unit.empty() ? "" : ", ", int(s.unit.size()), s.unit.data(), int(trig.size()),
                        trig.data());
    ImGui::EndTooltip();
}

} // namespace

bool paramWidget(Viewer& viewer, const SceneParam& param, float vectorSpeed) {
    const ValueSpec& s = *param.spec;
    const std::string label(s.name().empty() ? s.key : s.name());
    ParamValue value = param.get(viewer.scene());
    bool changed = false;
    ImGui::PushID(param.key.c_str());
    if (s.type == ParamType::Bool) {   // stored as 0 / 1
        bool on = std::get<std::int64_t>(value) != 0;
        if (ImGui::Checkbox(label.c_str(), &on)) {
            value = std::int64_t(on ? 1 : 0);
            changed = true;
        }
    } else switch (s.type) {
    case ParamType::Int:
    case ParamType::UInt: {
        // Drag speed grows with the range so seeds and sample counts stay usable.
        long long v = std::get<std::int64_t>(value);
        const long long lo = s.min ? (long long)std::ceil(s.min->value) : std::numeric_limits<int>::min();
        const long long hi = s.max ? (long long)std::floor(s.max->value) : std::numeric_limits<int>::max();
        const float speed = float(std::max(1.0, std::abs(double(v)) * 0.01));
        if (ImGui::DragScalar(label.c_str(), ImGuiDataType_S64, &v, speed, &lo, &hi, nullptr, ImGuiSliderFlags_AlwaysClamp)) {
            value = std::int64_t(v);
            changed = true;
        }
        break;
    }
    case ParamType::Float: {
        float v = float(std::get<double>(value));
        const float lo = lowerOf(s, -1e6f);
        const float hi = upperOf(s, 1e6f);
        const float speed = std::max(0.001f, std::abs(v) * 0.01f);
        if (ImGui::DragFloat(label.c_str(), &v, speed, lo, hi, "%.4g", ImGuiSliderFlags_AlwaysClamp)) {
            // An open lower bound (fov > 0) must not be reached by the clamp.
            if (s.min && !s.min->inclusive && v <= float(s.min->value)) v = float(s.min->value) + 1e-3f;
            if (s.max && !s.max->inclusive && v >= float(s.max->value)) v = float(s.max->value) - 1e-3f;
            value = double(v);
            changed = true;
        }
        break;
    }
    case ParamType::Vec3:
    case ParamType::Rgb: {
        glm::vec3 v = std::get<glm::vec3>(value);
        const bool colour = s.type == ParamType::Rgb && s.max && s.max->value <= 1.0;
        if (colour) {
            changed = ImGui::ColorEdit3(label.c_str(), &v[0], ImGuiColorEditFlags_Float);
            v = glm::clamp(v, glm::vec3(0.0f), glm::vec3(1.0f));
        } else if (s.type == ParamType::Rgb) {
            changed = ImGui::DragFloat3(label.c_str(), &v[0], 0.01f, lowerOf(s, 0.0f), upperOf(s, 1e6f), "%.3f");
        } else {
            changed = ImGui::DragFloat3(label.c_str(), &v[0], vectorSpeed, 0.0f, 0.0f, "%.4g");
        }
        if (changed) value = v;
        break;
    }
    case ParamType::Enum: {
        const std::int64_t v = std::get<std::int64_t>(value);
        const std::string current(s.enumName(v));
        if (ImGui::BeginCombo(label.c_str(), current.c_str())) {
            for (const EnumName& n : s.enumNames) {
                if (n.alias) continue;
                const std::string name(n.name);
                if (ImGui::Selectable(name.c_str(), n.value == v)) {
                    value = std::int64_t(n.value);
                    changed = true;
                }
            }
            ImGui::EndCombo();
        }
        break;
    }
    default:
        ImGui::TextDisabled("%s: %.*s", label.c_str(), int(typeName(s.type).size()), typeName(s.type).data());
        break;
    }
    tooltip(s);
    ImGui::PopID();
    if (changed && !checkValue(s, value)) return viewer.document().set(param, value);
    return false;
}

} // namespace raylab::ui
