#include "scene/scene_keys.h"

#include "scene/json_parse.h"
#include "scene/json_path.h"
#include "scene/scene_builder.h"
#include "scene/scene_error.h"

#include <algorithm>
#include <charconv>
#include <optional>

namespace raylab {
namespace {

using scenefmt::Json;
using scenefmt::JsonPath;
using scenefmt::ValidationFailure;

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

double number(const nlohmann::json& j, std::string_view key) {
    if (!j.is_number()) throw EditError(std::string(key) + ": expected a number, got " + j.dump());
    return j.get<double>();
}

// A JSON value, or a bare word taken as a string (aces, textures/glow.png). Parsed by the scene
// file's parser, so its depth limit holds here too: a value nested too deeply is an error at its
// character, not a bare word.
Json textValue(std::string_view text, std::string_view key) {
    scenefmt::ParseResult parsed = scenefmt::parseJson(text);
    if (parsed.ok) return std::move(parsed.doc);
    if (parsed.errorPath)
        throw EditError(std::string(key) + ": " + parsed.reason + " (the value's character " +
                        std::to_string(parsed.errorOffset + 1) + ")");
    return std::string(text);
}

// Runs one of the loader's checks; its complaint becomes an EditError at the document path.
template <class Check>
void asLoaderChecks(Check&& check) {
    try {
        check();
    } catch (const ValidationFailure& f) {
        throw EditError(f.path.display() + ": " + f.message);
    }
}

// The loader's cross-field checks that a scene-table key can break.
void checkSection(Scene& scene, std::string_view section) {
    asLoaderChecks([&] {
        if (section == "camera") scenefmt::checkCamera(scene.camera);
        if (section == "sky") scenefmt::readSkyMap(Json::object(), scene);
    });
}

SceneParam sceneTableKey(const ParamSpec& p, std::string_view key) {
    SceneParam k{std::string(key), &p, p.get, nullptr, nullptr, p.trigger};
    k.set = [&p](Scene& sc, const ParamValue& v) {
        const ParamValue old = p.get(sc);
        p.set(sc, v);
        try {
            checkSection(sc, p.section());
        } catch (const EditError&) {
            p.set(sc, old);
            throw;
        }
    };
    return k;
}

SceneParam skyMapKey(std::string_view key) {
    SceneParam k;
    k.key = std::string(key);
    k.setText = [key = k.key](Scene& sc, std::string_view text) {
        const Json root = {{"sky", {{"map", textValue(text, key)}}}};
        asLoaderChecks([&] { scenefmt::readSkyMap(root, sc); });
    };
    return k;
}

// A key of a per-item table (a material's, a sphere's), reached through `item`, which gives the
// material or sphere of a scene.
template <class Target, class Item>
std::optional<SceneParam> itemKey(const std::vector<FieldSpec<Target>>& table, std::string_view field,
                                  std::string_view key, Item item) {
    for (const FieldSpec<Target>& s : table) {
        if (s.key != field) continue;
        return SceneParam{std::string(key), &s, [&s, item](const Scene& sc) { return s.get(item(sc)); },
                          [&s, item](Scene& sc, const ParamValue& v) { s.set(item(sc), v); }, nullptr, s.trigger};
    }
    return std::nullopt;
}

SceneParam materialKey(const Scene& scene, std::string_view key, std::string_view item, std::string_view field) {
    std::optional<std::size_t> index = parseIndex(item);
    if (!index) {
        for (std::size_t i = 0; i < scene.materials.size(); ++i)
            if (scene.materials[i].name == item) index = i;
    }
    if (!index || *index >= scene.materials.size())
        throw EditError(std::string(key) + ": no material '" + std::string(item) + "'");
    const std::size_t i = *index;
    if (auto k = itemKey(materialParameters(), field, key, [i](auto& sc) -> auto& { return sc.materials.at(i); }))
        return *k;
    for (const TextureSlot& slot : textureSlots()) {
        if (slot.key != field) continue;
        SceneParam k;
        k.key = std::string(key);
        k.setText = [&slot, i, key = k.key](Scene& sc, std::string_view text) {
            Material m = sc.materials.at(i);
            const JsonPath at = JsonPath{}.key("materials").key(m.name).key(slot.key);
            asLoaderChecks([&] {
                scenefmt::readTextureSlot(slot, textValue(text, key), at, sc.sourcePath.parent_path(), sc.textures, m);
            });
            sc.materials.at(i) = std::move(m);
        };
        return k;
    }
    std::string keys = keysOf(materialParameters());
    for (std::string_view f : materialFileKeys()) keys += ", " + std::string(f);
    throw EditError(std::string(key) + ": materials have no key '" + std::string(field) + "' (keys: " + keys + ")");
}

// An object's `material`: a defined material's name, or "default" (built in when the file has none).
SceneParam objectMaterialKey(std::string_view key, bool mesh, std::size_t i, const JsonPath& at) {
    SceneParam k;
    k.key = std::string(key);
    k.setText = [mesh, i, at, key = k.key](Scene& sc, std::string_view text) {
        const Json v = textValue(text, key);
        std::vector<std::string_view> names;
        for (const Material& m : sc.materials)
            if (!m.fromGltf) names.push_back(m.name);
        asLoaderChecks([&] {
            if (!v.is_string())
                scenefmt::fail(at, "expected a material name (a string), got " + scenefmt::typeOf(v));
            const std::string& name = v.get_ref<const std::string&>();
            if (std::find(names.begin(), names.end(), name) == names.end() && name != "default")
                scenefmt::fail(at, "unknown material " + scenefmt::inQuotes(name) +
                                       scenefmt::suggestion(name, names, "defined materials"));
        });
        const std::string& name = v.get_ref<const std::string&>();
        auto found = std::find_if(sc.materials.begin(), sc.materials.end(),
                                  [&name](const Material& m) { return !m.fromGltf && m.name == name; });
        if (found == sc.materials.end()) {
            Material d;
            d.name = name;
            sc.materials.push_back(d);
            found = sc.materials.end() - 1;
        }
        const int index = int(found - sc.materials.begin());
        if (mesh) {
            sc.meshes.at(i).material = index;
            sc.meshes.at(i).triangleMaterials.clear();   // an object's material covers the whole mesh
        } else {
            sc.spheres.at(i).material = index;
        }
    };
    return k;
}

// A mesh's displacement key (objects.N.displacement_*): the mesh is tessellated and displaced again
// from its shape as given, with the loader's checks.
std::optional<SceneParam> displacementKey(std::string_view key, std::size_t i, std::size_t object, std::string_view field) {
    const JsonPath at = JsonPath{}.key("objects").index(object);
    auto redisplace = [i, at](Scene& sc, MeshDisplacement d) {
        asLoaderChecks([&] { scenefmt::redisplaceMesh(sc.meshes.at(i), std::move(d), at, sc.sourcePath.parent_path()); });
    };
    if (field == "displacement_texture") {
        SceneParam k;
        k.key = std::string(key);
        k.setText = [redisplace, i, at, key = k.key](Scene& sc, std::string_view text) {
            MeshDisplacement d = sc.meshes.at(i).displacement;
            const Json v = textValue(text, key);
            asLoaderChecks([&] { d.texture = scenefmt::imageKey(v, at.key("displacement_texture")); });
            redisplace(sc, std::move(d));
        };
        return k;
    }
    for (const DisplacementParamSpec& s : displacementParameters()) {
        if (s.key != field) continue;
        return SceneParam{std::string(key), &s, [&s, i](const Scene& sc) { return s.get(sc.meshes.at(i).displacement); },
                          [&s, i, redisplace](Scene& sc, const ParamValue& v) {
                              MeshDisplacement d = sc.meshes.at(i).displacement;
                              s.set(d, v);
                              redisplace(sc, std::move(d));
                          },
                          nullptr, s.trigger};
    }
    return std::nullopt;
}

SceneParam objectKey(const Scene& scene, std::string_view key, std::string_view item, std::string_view field) {
    const std::optional<std::size_t> index = parseIndex(item);
    const std::size_t count = scene.spheres.size() + scene.meshes.size();
    if (!index || *index >= count)
        throw EditError(std::string(key) + ": no object " + std::string(item) + " (the scene has " +
                       std::to_string(count) + ": spheres, then meshes)");
    const bool mesh = *index >= scene.spheres.size();
    const std::size_t i = mesh ? *index - scene.spheres.size() : *index;
    if (!mesh) {
        if (auto k = itemKey(sphereParameters(), field, key, [i](auto& sc) -> auto& { return sc.spheres.at(i); }))
            return *k;
    }
    for (const TransformParamSpec& s : transformParameters()) {
        if (s.key != field) continue;
        auto transformOf = [mesh, i](auto& sc) -> auto& { return mesh ? sc.meshes.at(i).transform : sc.spheres.at(i).transform; };
        return SceneParam{std::string(key), &s, [&s, transformOf](const Scene& sc) { return s.get(transformOf(sc)); },
                        [&s, transformOf, mesh, key = std::string(key)](Scene& sc, const ParamValue& v) {
                            Transform t = transformOf(sc);
                            s.set(t, v);
                            // A sphere stays a sphere (the loader checks the same).
                            if (!mesh && (t.scale.x != t.scale.y || t.scale.x != t.scale.z))
                                throw EditError(key + ": a sphere's scale must be the same on all three axes");
                            transformOf(sc) = t;
                        },
                        nullptr, s.trigger};
    }
    if (field == "material")
        return objectMaterialKey(key, mesh, i, JsonPath{}.key("objects").index(*index).key("material"));
    if (mesh)
        if (auto k = displacementKey(key, i, *index, field)) return *k;
    std::string keys = mesh ? "" : keysOf(sphereParameters()) + ", ";
    throw EditError(std::string(key) + ": " + (mesh ? "meshes" : "spheres") + " have no key '" + std::string(field) +
                   "' (keys: " + keys + keysOf(transformParameters()) + ", material" +
                   (mesh ? ", displacement_texture, " + keysOf(displacementParameters()) : "") + ")");
}

// A light's key (lights.N.FIELD) among its type's keys, checked as the loader checks the light.
SceneParam lightKey(const Scene& scene, std::string_view key, std::string_view item, std::string_view field) {
    const std::optional<std::size_t> index = parseIndex(item);
    if (!index || *index >= scene.lights.size())
        throw EditError(std::string(key) + ": no light " + std::string(item) + " (the scene has " +
                        std::to_string(scene.lights.size()) + ")");
    const std::size_t i = *index;
    const std::vector<std::string_view> own = lightKeysOf(scene.lights[i].type);
    for (const LightParamSpec& s : lightParameters()) {
        if (s.name() != field || std::find(own.begin(), own.end(), field) == own.end()) continue;
        return SceneParam{std::string(key), &s, [&s, i](const Scene& sc) { return s.get(sc.lights.at(i)); },
                          [&s, i, key = std::string(key)](Scene& sc, const ParamValue& v) {
                              Light l = sc.lights.at(i);
                              s.set(l, v);
                              if (s.name() == "intensity") l.power = 0.0f;   // the one given wins, as in the file
                              if (!(glm::length(l.direction) > 0.0f)) throw EditError(key + ": must be a non-zero direction");
                              if (l.innerAngle > l.outerAngle)
                                  throw EditError(key + ": inner_angle must not exceed outer_angle");
                              sc.lights.at(i) = l;
                          },
                          nullptr, s.trigger};
    }
    std::string keys;
    for (std::string_view k : own) keys += (keys.empty() ? "" : ", ") + std::string(k);
    throw EditError(std::string(key) + ": this light has no key '" + std::string(field) + "' (keys: " + keys + ")");
}

} // namespace

std::vector<std::string> splitKey(std::string_view key) {
    std::vector<std::string> segments;
    for (std::size_t start = 0;;) {
        const auto dot = key.find('.', start);
        segments.emplace_back(key.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start));
        if (dot == std::string_view::npos) break;
        start = dot + 1;
    }
    for (const std::string& s : segments)
        if (s.empty())
            throw EditError("the key '" + std::string(key) + "' has an empty part; write it like render.spp");
    return segments;
}

SceneParam resolveParam(const Scene& scene, std::string_view key) {
    const std::vector<std::string> parts = splitKey(key);
    if (const ParamSpec* p = findParameter(key)) return sceneTableKey(*p, key);
    if (key == "sky.map") return skyMapKey(key);
    if ((parts[0] == "materials" || parts[0] == "objects" || parts[0] == "lights") && parts.size() >= 3) {
        const std::string_view field = key.substr(parts[0].size() + parts[1].size() + 2);
        if (parts[0] == "materials") return materialKey(scene, key, parts[1], field);
        if (parts[0] == "lights") return lightKey(scene, key, parts[1], field);
        return objectKey(scene, key, parts[1], field);
    }
    std::vector<std::string_view> candidates;
    for (const ParamSpec& p : sceneParameters()) candidates.push_back(p.key);
    candidates.push_back("sky.map");
    std::string msg = "unknown key '" + std::string(key) + "'";
    const std::string_view near = closestMatch(key, candidates);
    if (!near.empty()) msg += "; did you mean '" + std::string(near) + "'?";
    throw EditError(msg);
}

std::vector<std::string> sceneKeys(const Scene& scene) {
    std::vector<std::string> keys;
    for (const ParamSpec& p : sceneParameters()) keys.emplace_back(p.key);
    keys.emplace_back("sky.map");
    for (const Material& m : scene.materials) {
        if (m.fromGltf) continue;   // the mesh's file holds them
        for (const MaterialParamSpec& p : materialParameters()) keys.push_back("materials." + m.name + "." + std::string(p.key));
        for (std::string_view f : materialFileKeys()) keys.push_back("materials." + m.name + "." + std::string(f));
    }
    const std::size_t count = scene.spheres.size() + scene.meshes.size();
    for (std::size_t i = 0; i < count; ++i) {
        const std::string prefix = "objects." + std::to_string(i) + ".";
        if (i < scene.spheres.size())
            for (const SphereParamSpec& p : sphereParameters()) keys.push_back(prefix + std::string(p.key));
        for (const TransformParamSpec& p : transformParameters()) keys.push_back(prefix + std::string(p.key));
        keys.push_back(prefix + "material");
        if (i >= scene.spheres.size()) {
            keys.push_back(prefix + "displacement_texture");
            for (const DisplacementParamSpec& p : displacementParameters()) keys.push_back(prefix + std::string(p.key));
        }
    }
    for (std::size_t i = 0; i < scene.lights.size(); ++i)
        for (std::string_view k : lightKeysOf(scene.lights[i].type)) keys.push_back("lights." + std::to_string(i) + "." + std::string(k));
    return keys;
}

ParamValue parseParamValue(const ValueSpec& spec, std::string_view text) {
    const std::string key(spec.key);
    nlohmann::json j = textValue(text, key);   // a bare word: an enum name
    ParamValue value;
    switch (spec.type) {
    case ParamType::Bool:
        if (j.is_string()) j = j.get<std::string>() == "true" ? nlohmann::json(true) : j.get<std::string>() == "false" ? nlohmann::json(false) : j;
        if (j.is_number_integer() && (j.get<long long>() == 0 || j.get<long long>() == 1)) j = j.get<long long>() == 1;
        if (!j.is_boolean()) throw EditError(key + ": expected true or false, got " + j.dump());
        return std::int64_t(j.get<bool>() ? 1 : 0);
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
        // A colour, or a transform's scale, may be one number for all three components (as in the file).
        if ((spec.type == ParamType::Rgb || spec.key == "transform.scale") && j.is_number()) {
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
    }
    if (auto why = checkValue(spec, value)) throw EditError(key + ": " + *why);
    return value;
}

Trigger setParam(Scene& scene, const SceneParam& param, const ParamValue& value) {
    if (!param.spec) throw EditError(param.key + ": names a file or a material; set it as text");
    if (auto why = checkValue(*param.spec, value)) throw EditError(param.key + ": " + *why);
    param.set(scene, value);
    return param.trigger;
}

Trigger setParam(Scene& scene, std::string_view key, std::string_view valueText) {
    const SceneParam param = resolveParam(scene, key);
    if (!param.spec) {
        param.setText(scene, valueText);
        return param.trigger;
    }
    try {
        return setParam(scene, param, parseParamValue(*param.spec, valueText));
    } catch (const EditError& e) {
        // A per-item table's complaint names its field ("displacement_scale: ..."): name the whole key.
        const std::string what = e.what(), field = std::string(param.spec->key) + ": ";
        if (param.key == param.spec->key || what.rfind(field, 0) != 0) throw;
        throw EditError(param.key + ": " + what.substr(field.size()));
    }
}

} // namespace raylab
