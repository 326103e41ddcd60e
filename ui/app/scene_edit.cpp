#include "app/scene_edit.h"

#include "app/scene_object.h"

#include <nlohmann/json.hpp>

#include <charconv>
#include <cmath>

namespace raylab::ui {
namespace {

std::optional<std::size_t> parseIndex(std::string_view s) {
    std::size_t v = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || p != s.data() + s.size()) return std::nullopt;
    return v;
}

template <class T>
std::string keysOf(const std::vector<FieldSpec<T>>& table) {
    std::string out;
    for (const auto& s : table) out += (out.empty() ? "" : ", ") + std::string(s.key);
    return out;
}

[[noreturn]] void unknownKey(std::string_view key, const std::vector<std::string_view>& candidates) {
    std::string msg = "unknown key '" + std::string(key) + "'";
    const std::string_view near = closestMatch(key, candidates);
    if (!near.empty()) msg += "; did you mean '" + std::string(near) + "'?";
    throw EditError(msg);
}

double number(const nlohmann::json& j, std::string_view key) {
    if (!j.is_number()) throw EditError(std::string(key) + ": expected a number, got " + j.dump());
    return j.get<double>();
}

} // namespace

SceneParam resolveParam(const Scene& scene, std::string_view key) {
    if (const ParamSpec* p = findParameter(key)) {
        return SceneParam{std::string(key), p, p->get, p->set};
    }
    const auto dot1 = key.find('.');
    const auto dot2 = dot1 == std::string_view::npos ? dot1 : key.find('.', dot1 + 1);
    const std::string_view section = key.substr(0, dot1);
    if ((section == "materials" || section == "objects") && dot2 != std::string_view::npos) {
        const std::string_view item = key.substr(dot1 + 1, dot2 - dot1 - 1);
        const std::string_view field = key.substr(dot2 + 1);
        if (section == "materials") {
            std::optional<std::size_t> index = parseIndex(item);
            if (!index) {
                for (std::size_t i = 0; i < scene.materials.size(); ++i)
                    if (scene.materials[i].name == item) index = i;
            }
            if (!index || *index >= scene.materials.size())
                throw EditError(std::string(key) + ": no material '" + std::string(item) + "'");
            const std::size_t i = *index;
            for (const MaterialParamSpec& s : materialParameters()) {
                if (s.key != field) continue;
                return SceneParam{std::string(key), &s,
                                  [&s, i](const Scene& sc) { return s.get(sc.materials.at(i)); },
                                  [&s, i](Scene& sc, const ParamValue& v) { s.set(sc.materials.at(i), v); }};
            }
            throw EditError(std::string(key) + ": materials have no key '" + std::string(field) +
                            "' (keys: " + keysOf(materialParameters()) + ")");
        }
        const std::optional<std::size_t> index = parseIndex(item);
        const std::optional<ObjectRef> object = index ? objectRef(scene, int(*index)) : std::nullopt;
        if (!object)
            throw EditError(std::string(key) + ": no object " + std::string(item) + " (the scene has " +
                            std::to_string(objectCount(scene)) + ": spheres, then meshes)");
        const std::size_t i = std::size_t(object->index);
        if (!object->mesh) {
            for (const SphereParamSpec& s : sphereParameters()) {
                if (s.key != field) continue;
                return SceneParam{std::string(key), &s,
                                  [&s, i](const Scene& sc) { return s.get(sc.spheres.at(i)); },
                                  [&s, i](Scene& sc, const ParamValue& v) { s.set(sc.spheres.at(i), v); }};
            }
        }
        for (const TransformParamSpec& s : transformParameters()) {
            if (s.key != field) continue;
            const bool mesh = object->mesh;
            auto transformOf = [mesh, i](auto& sc) -> auto& { return mesh ? sc.meshes.at(i).transform : sc.spheres.at(i).transform; };
            return SceneParam{std::string(key), &s, [&s, transformOf](const Scene& sc) { return s.get(transformOf(sc)); },
                              [&s, transformOf, mesh, key = std::string(key)](Scene& sc, const ParamValue& v) {
                                  Transform t = transformOf(sc);
                                  s.set(t, v);
                                  // A sphere stays a sphere (the loader checks the same).
                                  if (!mesh && (t.scale.x != t.scale.y || t.scale.x != t.scale.z))
                                      throw EditError(key + ": a sphere's scale must be the same on all three axes");
                                  transformOf(sc) = t;
                              }};
        }
        std::string keys = object->mesh ? "" : keysOf(sphereParameters()) + ", ";
        throw EditError(std::string(key) + ": " + (object->mesh ? "meshes" : "spheres") + " have no key '" +
                        std::string(field) + "' (keys: " + keys + keysOf(transformParameters()) + ")");
    }
    std::vector<std::string_view> candidates;
    for (const ParamSpec& p : sceneParameters()) candidates.push_back(p.key);
    unknownKey(key, candidates);
}

ParamValue parseParamValue(const ValueSpec& spec, std::string_view text) {
    nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded()) j = std::string(text);   // a bare word: an enum name
    const std::string key(spec.key);
    ParamValue value;
    // Booleans (render.nee, render.mis on the materials branch) are stored as 0 / 1; matched by
    // name so this file builds before and after that type exists.
    if (typeName(spec.type) == "bool") {
        if (j.is_string()) j = j.get<std::string>() == "true" ? nlohmann::json(true) : j.get<std::string>() == "false" ? nlohmann::json(false) : j;
        if (j.is_number_integer() && (j.get<long long>() == 0 || j.get<long long>() == 1)) j = j.get<long long>() == 1;
        if (!j.is_boolean()) throw EditError(key + ": expected true or false, got " + j.dump());
        return std::int64_t(j.get<bool>() ? 1 : 0);
    }
    switch (spec.type) {
    case ParamType::Int:
    case ParamType::UInt: {
        const double d = number(j, key);
        if (auto why = checkScalar(spec, d)) throw EditError(key + ": " + *why);
        value = std::int64_t(d);
        break;
    }
    case ParamType::Float:
        value = number(j, key);
        break;
    case ParamType::Vec3:
    case ParamType::Rgb: {
        if (spec.type == ParamType::Rgb && j.is_number()) {
            value = glm::vec3(float(j.get<double>()));
            break;
        }
        if (!j.is_array() || j.size() != 3)
            throw EditError(key + ": expected [x, y, z]" +
                            std::string(spec.type == ParamType::Rgb ? " or one number" : "") + ", got " + j.dump());
        value = glm::vec3(float(number(j[0], key)), float(number(j[1], key)), float(number(j[2], key)));
        break;
    }
    case ParamType::Enum: {
        if (!j.is_string()) throw EditError(key + ": expected a name, got " + j.dump());
        const EnumName* e = spec.findEnum(j.get<std::string>());
        if (!e) {
            std::string names;
            for (const EnumName& n : spec.enumNames)
                if (!n.alias) names += (names.empty() ? "" : ", ") + std::string(n.name);
            throw EditError(key + ": unknown value '" + j.get<std::string>() + "' (expected " + names + ")");
        }
        value = std::int64_t(e->value);
        break;
    }
    default:
        throw EditError(key + ": cannot edit a value of type " + std::string(typeName(spec.type)));
    }
    if (auto why = checkValue(spec, value)) throw EditError(key + ": " + *why);
    return value;
}

Trigger setParam(Scene& scene, const SceneParam& param, const ParamValue& value) {
    if (auto why = checkValue(*param.spec, value)) throw EditError(param.key + ": " + *why);
    param.set(scene, value);
    return param.spec->trigger;
}

Trigger setParam(Scene& scene, std::string_view key, std::string_view valueText) {
    const SceneParam param = resolveParam(scene, key);
    return setParam(scene, param, parseParamValue(*param.spec, valueText));
}

} // namespace raylab::ui
