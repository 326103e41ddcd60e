#include "script/expectation.h"

#include "render/debug_views.h"
#include "scene/scene_keys.h"

#include <charconv>
#include <cmath>
#include <variant>

namespace raylab {
namespace {

// Float keys are stored as float: equal when they round to the same float.
bool sameNumber(double a, double b) { return float(a) == float(b) || std::abs(a - b) <= 1e-6 * std::abs(b); }

bool sameValue(const ParamValue& a, const ParamValue& b) {
    if (a.index() != b.index()) return false;
    if (const auto* i = std::get_if<std::int64_t>(&a)) return *i == std::get<std::int64_t>(b);
    if (const auto* d = std::get_if<double>(&a)) return sameNumber(*d, std::get<double>(b));
    const glm::vec3 u = std::get<glm::vec3>(a), v = std::get<glm::vec3>(b);
    return sameNumber(u.x, v.x) && sameNumber(u.y, v.y) && sameNumber(u.z, v.z);
}

std::optional<double> number(const std::string& text) {
    double v = 0;
    const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
    if (ec != std::errc() || p != text.data() + text.size()) return std::nullopt;
    return v;
}

std::string viewFailure(const ViewState& view, const std::string& what, const std::string& value) {
    if (what == "debug-view") {
        if (!parseDebugView(value)) return "unknown debug view '" + value + "'";
        return view.debugView == value ? "" : "the debug view is " + view.debugView + ", expected " + value;
    }
    if (what == "scale") {
        const auto s = number(value);
        if (!s) return "expect scale takes a number";
        if (view.scale < 0.0) return "the resolution scale is not known here (set it with scale S first)";
        return sameNumber(view.scale, *s) ? "" : "the resolution scale is " + formatNumber(view.scale) + ", expected " + value;
    }
    const auto k = value == "off" ? std::optional<double>(0.0) : number(value);
    if (!k) return "expect bounce-step takes a number or off";
    return view.bounceStep == int(*k) ? ""
                                      : "bounce stepping is at " + std::to_string(view.bounceStep) + ", expected " + value;
}

} // namespace

std::string expectationFailure(const Scene& scene, const ViewState& view, const std::string& what,
                               const std::string& value) {
    if (what == "debug-view" || what == "scale" || what == "bounce-step") return viewFailure(view, what, value);
    try {
        const SceneParam param = resolveParam(scene, what);
        if (!param.spec || !param.get) return what + " names a file or a name; expect a key of the parameter table";
        const ParamValue wanted = parseParamValue(*param.spec, value);
        const ParamValue actual = param.get(scene);
        if (sameValue(actual, wanted)) return {};
        return what + " is " + formatValue(*param.spec, actual) + ", expected " + formatValue(*param.spec, wanted);
    } catch (const EditError& e) {
        return e.what();
    }
}

} // namespace raylab
