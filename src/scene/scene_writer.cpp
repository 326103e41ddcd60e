#include "scene/scene_writer.h"

#include "scene/parameters.h"
#include "scene/scene_error.h"

#include <algorithm>
#include <charconv>
#include <string>
#include <variant>

namespace raylab {
namespace {

namespace fs = std::filesystem;

fs::path absoluteDirectory(const fs::path& dir) {
    fs::path d = fs::absolute(dir.empty() ? fs::path(".") : dir).lexically_normal();
    if (d.filename().empty() && d.has_relative_path()) d = d.parent_path();   // "/a/b/" -> "/a/b"
    return d;
}

// `given` (relative to `from`) as a path relative to `to`; absolute when no relative path exists.
std::string rebased(const std::string& given, const fs::path& from, const fs::path& to) {
    const fs::path file = (from / given).lexically_normal();   // an absolute `given` stays itself
    const fs::path relative = file.lexically_relative(to);
    return (relative.empty() ? file : relative).string();
}

// Calls `visit` on each string value of a path key of `scope` in `doc`.
template <class Visit>
void forEachPath(nlohmann::json& doc, const PathKey& key, Visit visit) {
    auto at = [&visit](nlohmann::json& holder, std::string_view name) {
        if (!holder.is_object()) return;
        const auto it = holder.find(std::string(name));
        if (it != holder.end() && it->is_string()) visit(*it);
    };
    auto each = [&](std::string_view list) {
        const auto it = doc.find(std::string(list));
        if (it == doc.end()) return;
        if (it->is_object()) {
            for (auto& [name, item] : it->items()) at(item, key.key);
        } else if (it->is_array()) {
            for (nlohmann::json& item : *it) at(item, key.key);
        }
    };
    switch (key.scope) {
    case PathScope::Scene: {
        const std::string_view dotted = key.key;
        const std::size_t dot = dotted.find('.');
        const auto section = doc.find(std::string(dotted.substr(0, dot)));
        if (section != doc.end()) at(*section, dotted.substr(dot + 1));
        break;
    }
    case PathScope::Material: each("materials"); break;
    case PathScope::Object: each("objects"); break;
    }
}

// JSON number for a value as it will be read back: the shortest text that gives back the same field.
double shortestText(double value) {
    const std::string text = formatNumber(value);
    double d = value;
    std::from_chars(text.data(), text.data() + text.size(), d);
    return d;
}

// For a float field 0.8f is written as 0.8; a double field keeps its exact value when 0.8 would differ.
template <class Target>
double numberForField(const FieldSpec<Target>& spec, const Target& source, double value) {
    const double shortest = shortestText(value);
    Target scratch = source;
    spec.set(scratch, shortest);
    return spec.get(scratch) == spec.get(source) ? shortest : value;
}

template <class Target>
nlohmann::json valueJson(const FieldSpec<Target>& spec, const Target& source) {
    const ParamValue v = spec.get(source);
    if (const auto* vec = std::get_if<glm::vec3>(&v)) {
        nlohmann::json arr = nlohmann::json::array();
        // Components are floats: their shortest float text reads back to the same float.
        for (int i = 0; i < 3; ++i) arr.push_back(shortestText(static_cast<double>((*vec)[i])));
        return arr;
    }
    if (const auto* d = std::get_if<double>(&v)) return numberForField(spec, source, *d);
    const std::int64_t i = std::get<std::int64_t>(v);
    if (spec.type == ParamType::Enum) return std::string(spec.enumName(i));
    if (spec.type == ParamType::Bool) return i != 0;
    return i;
}

nlohmann::json transformJson(const Transform& t) {
    nlohmann::json j = nlohmann::json::object();
    for (const TransformParamSpec& spec : transformParameters()) j[std::string(spec.name())] = valueJson(spec, t);
    return j;
}

nlohmann::json materialJson(const Material& m) {
    nlohmann::json mj = nlohmann::json::object();
    for (const MaterialParamSpec& spec : materialParameters()) mj[std::string(spec.key)] = valueJson(spec, m);
    for (const TextureSlot& slot : textureSlots())
        if (!(m.*slot.file).empty()) mj[std::string(slot.key)] = m.*slot.file;
    return mj;
}

nlohmann::json meshJson(const Mesh& m, const std::string& material) {
    nlohmann::json o = nlohmann::json::object();
    o["type"] = "mesh";
    // A displaced inline mesh's arrays are written as they were given; loading displaces them again.
    const Mesh& given = m.displacement.source ? *m.displacement.source : m;
    if (!m.file.empty()) {
        o["file"] = m.file;
    } else {
        auto flat = [](const auto& items, int n) {
            nlohmann::json a = nlohmann::json::array();
            for (const auto& v : items)
                for (int k = 0; k < n; ++k) a.push_back(v[k]);
            return a;
        };
        o["positions"] = flat(given.positions, 3);
        o["indices"] = flat(given.triangles, 3);
        if (!given.normals.empty()) o["normals"] = flat(given.normals, 3);
        if (!given.uvs.empty()) o["uvs"] = flat(given.uvs, 2);
    }
    o["transform"] = transformJson(m.transform);
    if (m.triangleMaterials.empty()) o["material"] = material;   // else the glTF file's materials
    if (m.emissionSides == EmissionSides::Front) o["emission_sides"] = "front";
    if (m.emissionSides == EmissionSides::Gltf) o["emission_sides"] = "gltf";
    if (!m.displacement.texture.empty()) {
        o["displacement_texture"] = m.displacement.texture;
        for (const DisplacementParamSpec& spec : displacementParameters())
            o[std::string(spec.key)] = valueJson(spec, m.displacement);
    }
    return o;
}

// The light's type and the keys of that type; intensity or power, whichever it was given.
nlohmann::json lightJson(const Light& l) {
    nlohmann::json o = nlohmann::json::object();
    const std::vector<std::string_view> own = lightKeysOf(l.type);
    for (const LightParamSpec& spec : lightParameters()) {
        const std::string_view name = spec.name();
        if (name != "type" && std::find(own.begin(), own.end(), name) == own.end()) continue;
        if (name == (l.power > 0.0f ? "intensity" : "power")) continue;
        o[std::string(name)] = valueJson(spec, l);
    }
    return o;
}

} // namespace

void rebasePaths(nlohmann::json& doc, const fs::path& from, const fs::path& to) {
    const fs::path fromDir = absoluteDirectory(from), toDir = absoluteDirectory(to);
    for (const PathKey& key : pathKeys())
        forEachPath(doc, key, [&](nlohmann::json& v) { v = rebased(v.get<std::string>(), fromDir, toDir); });
}

nlohmann::json sceneToJson(const Scene& scene, const fs::path& savedFile) {
    nlohmann::json j = nlohmann::json::object();
    for (const ParamSpec& spec : sceneParameters())
        j[std::string(spec.section())][std::string(spec.name())] = valueJson(spec, scene);
    // render.adaptive at its default beside stratified or zsobol is off without being asked for;
    // written out it would be asked for, which the loader refuses.
    if (scene.render.adaptive && !adaptiveInEffect(scene.render)) j["render"].erase("adaptive");

    nlohmann::json materials = nlohmann::json::object();
    for (const Material& m : scene.materials) {
        if (m.fromGltf) continue;   // read again from the mesh's file
        materials[m.name] = materialJson(m);
    }
    j["materials"] = materials;
    // The loader keeps sky.map resolved, and textures and mesh files as written in the scene.
    if (!scene.sky.map.empty()) j["sky"]["map"] = fs::absolute(scene.sky.map).string();

    nlohmann::json objects = nlohmann::json::array();
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        if (s.material < 0 || static_cast<std::size_t>(s.material) >= scene.materials.size()) {
            throw SceneError("sceneToJson: error: objects[" + std::to_string(i) + "].material: index " +
                             std::to_string(s.material) + " is out of range (" +
                             std::to_string(scene.materials.size()) + " materials)");
        }
        nlohmann::json o = nlohmann::json::object();
        o["type"] = "sphere";
        for (const SphereParamSpec& spec : sphereParameters()) o[std::string(spec.key)] = valueJson(spec, s);
        o["transform"] = transformJson(s.transform);
        o["material"] = scene.materials[static_cast<std::size_t>(s.material)].name;
        objects.push_back(o);
    }
    for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
        const Mesh& m = scene.meshes[i];
        if (m.material < 0 || static_cast<std::size_t>(m.material) >= scene.materials.size()) {
            throw SceneError("sceneToJson: error: objects[" + std::to_string(scene.spheres.size() + i) +
                             "].material: index " + std::to_string(m.material) + " is out of range (" +
                             std::to_string(scene.materials.size()) + " materials)");
        }
        objects.push_back(meshJson(m, scene.materials[static_cast<std::size_t>(m.material)].name));
    }
    j["objects"] = objects;
    if (!scene.lights.empty()) {
        nlohmann::json lights = nlohmann::json::array();
        for (const Light& l : scene.lights) lights.push_back(lightJson(l));
        j["lights"] = lights;
    }
    const fs::path sceneDir = scene.sourcePath.parent_path();
    rebasePaths(j, sceneDir, savedFile.empty() ? sceneDir : savedFile.parent_path());
    return j;
}

} // namespace raylab
