#include "scene/scene_builder.h"

#include "mesh/displacement.h"
#include "scene/gltf_loader.h"
#include "scene/obj_loader.h"
#include "scene/scene_error.h"
#include "scene/sky_map.h"

#include "shaders/include/analytic_lights.glsl"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>

namespace raylab::scenefmt {
namespace {

constexpr std::string_view kDefaultMaterial = "default";
constexpr std::string_view kSectionKeys[] = {"camera", "render", "sky", "ao", "materials", "objects", "lights"};
constexpr int kMaxLights = glsl::MAX_ANALYTIC_LIGHTS;
constexpr std::string_view kObjectTypes[] = {"sphere", "mesh"};

double numberOf(const Json& v) {
    if (v.is_number_unsigned()) return static_cast<double>(v.get<std::uint64_t>());
    if (v.is_number_integer()) return static_cast<double>(v.get<std::int64_t>());
    return v.get<double>();
}

double readScalar(const ValueSpec& spec, const Json& v, const JsonPath& p) {
    if (!v.is_number()) {
        const bool integral = spec.type == ParamType::Int || spec.type == ParamType::UInt;
        fail(p, std::string(integral ? "expected an integer" : "expected a number") + ", got " + typeOf(v));
    }
    const double d = numberOf(v);
    if (auto err = checkScalar(spec, d)) fail(p, *err);
    return d;
}

ParamValue readValue(const ValueSpec& spec, const Json& v, const JsonPath& p) {
    switch (spec.type) {
    case ParamType::Int:
    case ParamType::UInt: return static_cast<std::int64_t>(readScalar(spec, v, p));
    case ParamType::Float: return readScalar(spec, v, p);
    case ParamType::Vec3:
    case ParamType::Rgb: {
        const bool rgb = spec.type == ParamType::Rgb;
        if (rgb && v.is_number()) return glm::vec3(static_cast<float>(readScalar(spec, v, p)));
        if (!v.is_array()) {
            fail(p, std::string(rgb ? "expected a colour, [r, g, b] or one number for grey"
                                    : "expected [x, y, z], an array of 3 numbers") +
                        ", got " + typeOf(v));
        }
        if (v.size() != 3) fail(p, "expected 3 numbers, got " + std::to_string(v.size()));
        glm::vec3 out{};
        for (std::size_t i = 0; i < 3; ++i)
            out[static_cast<glm::length_t>(i)] = static_cast<float>(readScalar(spec, v[i], p.index(i)));
        return out;
    }
    case ParamType::Bool:
        if (!v.is_boolean()) fail(p, "expected true or false, got " + typeOf(v));
        return static_cast<std::int64_t>(v.get<bool>() ? 1 : 0);
    case ParamType::Enum: {
        std::vector<std::string_view> names;
        for (const EnumName& e : spec.enumNames) names.push_back(e.name);
        if (!v.is_string()) fail(p, "expected a string (" + joinNames(names) + "), got " + typeOf(v));
        const std::string& s = v.get_ref<const std::string&>();
        const EnumName* e = spec.findEnum(s);
        if (!e) fail(p, "unknown value " + inQuotes(s) + suggestion(s, names, "allowed values"));
        return static_cast<std::int64_t>(e->value);
    }
    }
    fail(p, "internal error: unhandled parameter type");
}

// Reads the members of one JSON object through a table. Keys in `handledElsewhere` are skipped.
template <class Target>
void readMembers(const Json& obj, const JsonPath& p, const std::vector<FieldSpec<Target>>& table,
                 std::string_view section, Target& target,
                 const std::vector<std::string_view>& handledElsewhere = {}) {
    if (!obj.is_object()) fail(p, "expected an object { ... }, got " + typeOf(obj));
    std::vector<std::string_view> known(handledElsewhere);
    for (const auto& spec : table)
        if (spec.section() == section) known.push_back(spec.name());
    for (const auto& [k, v] : obj.items()) {
        if (std::find(handledElsewhere.begin(), handledElsewhere.end(), k) != handledElsewhere.end()) continue;
        const FieldSpec<Target>* spec = nullptr;
        for (const auto& s : table)
            if (s.section() == section && s.name() == k) spec = &s;
        if (!spec) {
            failUnknownKey(p, k, known);
        }
        spec->set(target, readValue(*spec, v, p.key(k)));
    }
}

struct PendingSphere {
    Sphere sphere;
    std::string material;
};

struct PendingMesh {
    Mesh mesh;
    std::string material;
    std::vector<Material> gltfMaterials;   // used when the object names no material (textures resolved)
};

} // namespace

// A key naming an image file: a non-empty string, relative to the scene file's directory.
std::string imageKey(const Json& v, const JsonPath& p) {
    if (!v.is_string() || v.get_ref<const std::string&>().empty())
        fail(p, "expected the path of an image file (a string), got " + typeOf(v));
    return v.get<std::string>();
}

std::filesystem::path resolvedPath(const std::string& given, const std::filesystem::path& sceneDir) {
    return std::filesystem::path(given).is_absolute() ? std::filesystem::path(given) : sceneDir / given;
}

Texture readImage(const std::filesystem::path& path, bool linearData, const JsonPath& p) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) fail(p, path.string() + ": cannot read: no such file");
    try {
        return loadTexture(path, linearData);
    } catch (const TextureError& e) {
        fail(p, e.what());
    }
}

void readTextureSlot(const TextureSlot& slot, const Json& v, const JsonPath& p, const std::filesystem::path& sceneDir,
                     std::vector<Texture>& textures, Material& material) {
    const std::string given = imageKey(v, p);
    material.*slot.file = given;
    const std::filesystem::path path = resolvedPath(given, sceneDir);
    const std::string key = (slot.linearData ? "linear:" : "srgb:") + given;   // one file, two decodings
    for (std::size_t i = 0; i < textures.size(); ++i) {
        if (textures[i].file == key) {
            material.*slot.index = int(i);
            return;
        }
    }
    Texture t = readImage(path, slot.linearData, p);
    t.file = key;
    textures.push_back(std::move(t));
    material.*slot.index = int(textures.size() - 1);
}

void redisplaceMesh(Mesh& mesh, MeshDisplacement d, const JsonPath& p, const std::filesystem::path& sceneDir) {
    // The shape as given: each of its triangles became a run of 4^levels consecutive ones (mesh/subdivision.cpp).
    Mesh next = mesh;
    if (const std::shared_ptr<const Mesh> given = mesh.displacement.source) {
        const std::size_t children = given->triangles.empty() ? 1 : mesh.triangles.size() / given->triangles.size();
        next.positions = given->positions;
        next.normals = given->normals;
        next.uvs = given->uvs;
        next.triangles = given->triangles;
        next.triangleMaterials.clear();
        if (!mesh.triangleMaterials.empty())
            for (std::size_t t = 0; t < given->triangles.size(); ++t)
                next.triangleMaterials.push_back(mesh.triangleMaterials[t * children]);
    }
    d.source = nullptr;
    d.trianglesBefore = 0;
    d.milliseconds = 0.0;
    next.displacement = d;
    if (!d.texture.empty()) {
        const JsonPath tp = p.key("displacement_texture");
        const Texture texture = readImage(resolvedPath(d.texture, sceneDir), true, tp);
        if (next.uvs.empty()) fail(tp, "the mesh has no uvs to read the displacement texture at");
        const std::size_t factor = std::size_t(1) << (2 * d.subdivision);
        if (next.triangles.size() > kMaxDisplacedTriangles / factor)
            fail(p.key("displacement_subdivision"),
                 std::to_string(next.triangles.size()) + " triangles x 4^" + std::to_string(d.subdivision) +
                     " exceed the limit of " + std::to_string(kMaxDisplacedTriangles) + " displaced triangles");
        next.displacement.source = std::make_shared<const Mesh>(next);
        displaceMesh(next, texture);
    }
    mesh = std::move(next);
}

namespace {

// Appends the items that `into` does not hold yet (by `same`); returns where each item now is.
template <class T, class Same>
std::vector<int> appendNew(std::vector<T>& into, std::vector<T>& items, Same same) {
    std::vector<int> where;
    for (T& item : items) {
        const auto known = std::find_if(into.begin(), into.end(), [&](const T& x) { return same(x, item); });
        where.push_back(int(known - into.begin()));
        if (known == into.end()) into.push_back(std::move(item));
    }
    return where;
}

// A glTF file's materials: its images join the scene's textures (once per file and texture), its
// materials wait in the pending mesh, named "FILE#materials[k] NAME", until the file's own
// materials are in place. An object that names a material keeps that one for the whole mesh.
void addGltfMaterials(GltfAsset gltf, bool objectNamesMaterial, PendingMesh& pending, Scene& scene) {
    for (std::string& w : gltf.warnings) scene.warnings.push_back(std::move(w));
    if (objectNamesMaterial || gltf.materials.empty()) {
        pending.mesh.triangleMaterials.clear();
        return;
    }
    const std::vector<int> textureIndex = appendNew(scene.textures, gltf.textures,
                                                    [](const Texture& a, const Texture& b) { return a.file == b.file; });
    auto remap = [&textureIndex](int& i) { i = i < 0 ? -1 : textureIndex[std::size_t(i)]; };
    for (Material& m : gltf.materials) {
        m.name = pending.mesh.file + "#" + m.name;
        remap(m.albedoTextureIndex);
        remap(m.normalTextureIndex);
        remap(m.roughnessTextureIndex);
        remap(m.metallicTextureIndex);
        remap(m.emissionTextureIndex);
        remap(m.specularTextureIndex);
        remap(m.occlusionTextureIndex);
        m.fromGltf = true;
    }
    pending.gltfMaterials = std::move(gltf.materials);
}

// "transform": { "translation", "rotation", "scale" }; scale may be one number for all axes.
Transform readTransform(const Json& o, const JsonPath& p) {
    Transform t;
    if (!o.contains("transform")) return t;
    const JsonPath tp = p.key("transform");
    Json copy = o["transform"];
    if (copy.is_object() && copy.contains("scale") && copy["scale"].is_number()) {
        const Json s = copy["scale"];
        copy["scale"] = Json::array({s, s, s});
        const ValueSpec& spec = transformParameters().back();
        readScalar(spec, s, tp.key("scale"));   // a bad single number is reported as itself
    }
    readMembers(copy, tp, transformParameters(), "transform", t);
    return t;
}

// A flat array of numbers (finite, single precision) whose length is a multiple of `group`.
std::vector<double> readNumbers(const Json& o, const char* key, const JsonPath& p, std::size_t group,
                                bool integers) {
    const JsonPath kp = p.key(key);
    const Json& v = o[key];
    if (!v.is_array())
        fail(kp, std::string("expected a flat array of ") + (integers ? "integers" : "numbers") + ", got " + typeOf(v));
    if (v.size() % group != 0)
        fail(kp, "expected a multiple of " + std::to_string(group) + " numbers, got " + std::to_string(v.size()));
    ValueSpec spec;
    spec.key = key;
    spec.type = integers ? ParamType::UInt : ParamType::Float;
    std::vector<double> out;
    out.reserve(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out.push_back(readScalar(spec, v[i], kp.index(i)));
    return out;
}

// "emission_sides": "both" (default), "front" or "gltf" (only for a mesh read from a glTF file).
EmissionSides readEmissionSides(const Json& o, const JsonPath& p, bool fromGltfFile) {
    if (!o.contains("emission_sides")) return EmissionSides::Both;
    const Json& v = o["emission_sides"];
    const std::vector<std::string_view> names = {"both", "front", "gltf"};
    if (!v.is_string()) fail(p.key("emission_sides"), "expected a string (both, front, gltf), got " + typeOf(v));
    const std::string& s = v.get_ref<const std::string&>();
    if (std::find(names.begin(), names.end(), s) == names.end())
        fail(p.key("emission_sides"), "unknown value " + inQuotes(s) + suggestion(s, names, "allowed values"));
    if (s == "gltf" && !fromGltfFile)
        fail(p.key("emission_sides"), "\"gltf\" takes the sides from a glTF file's materials (doubleSided); this mesh "
                                      "is not read from a .gltf or .glb file");
    return s == "front" ? EmissionSides::Front : s == "gltf" ? EmissionSides::Gltf : EmissionSides::Both;
}

// "displacement_texture" with its scale and subdivision level: the mesh is tessellated and displaced
// here, once (mesh/displacement.h). The image is data (linear), used on loading only.
void readDisplacement(const Json& o, const JsonPath& p, const std::filesystem::path& sceneDir, Mesh& mesh) {
    MeshDisplacement d;
    for (const DisplacementParamSpec& spec : displacementParameters())
        if (o.contains(spec.key)) spec.set(d, readValue(spec, o[std::string(spec.key)], p.key(spec.key)));
    if (o.contains("displacement_texture"))
        d.texture = imageKey(o["displacement_texture"], p.key("displacement_texture"));
    redisplaceMesh(mesh, std::move(d), p, sceneDir);
}

// A mesh object: inline arrays, or "file" (OBJ, relative to the scene file's directory).
Mesh readMesh(const Json& o, const JsonPath& p, const std::filesystem::path& sceneDir, GltfAsset* gltf) {
    std::vector<std::string_view> known = {"type", "material", "transform"};
    for (std::string_view k : meshKeys()) known.push_back(k);
    for (const DisplacementParamSpec& spec : displacementParameters()) known.push_back(spec.key);
    for (const auto& [k, v] : o.items()) {
        (void)v;
        if (std::find(known.begin(), known.end(), k) == known.end())
            failUnknownKey(p, k, known);
    }
    Mesh mesh;
    if (o.contains("file")) {
        for (const char* inline_ : {"positions", "indices", "normals", "uvs"})
            if (o.contains(inline_))
                fail(p.key(inline_), "a mesh takes either \"file\" or inline arrays, not both", true);
        const Json& f = o["file"];
        if (!f.is_string() || f.get_ref<const std::string&>().empty())
            fail(p.key("file"), "expected the path of an OBJ or glTF file (a string), got " + typeOf(f));
        const std::string given = f.get<std::string>();
        const std::filesystem::path path = std::filesystem::path(given).is_absolute() ? std::filesystem::path(given)
                                                                                     : sceneDir / given;
        std::string ext = path.extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        try {
            if (ext == ".gltf" || ext == ".glb") {
                *gltf = loadGltfAsset(path);
                mesh = std::move(gltf->mesh);
            } else {
                mesh = loadObj(path);
            }
        } catch (const ObjError& e) {
            fail(p.key("file"), e.what());
        } catch (const GltfError& e) {
            fail(p.key("file"), e.what());
        }
        mesh.file = given;
        mesh.emissionSides = readEmissionSides(o, p, ext == ".gltf" || ext == ".glb");
        return mesh;
    }
    for (const char* required : {"positions", "indices"})
        if (!o.contains(required))
            fail(p, std::string("a mesh needs \"") + required + "\" (or \"file\" with an OBJ path)");
    const std::vector<double> pos = readNumbers(o, "positions", p, 3, false);
    const std::vector<double> idx = readNumbers(o, "indices", p, 3, true);
    for (std::size_t i = 0; i < pos.size(); i += 3)
        mesh.positions.emplace_back(float(pos[i]), float(pos[i + 1]), float(pos[i + 2]));
    if (mesh.positions.empty()) fail(p.key("positions"), "a mesh needs at least one vertex");
    if (idx.empty()) fail(p.key("indices"), "a mesh needs at least one triangle");
    for (std::size_t i = 0; i < idx.size(); ++i)
        if (idx[i] >= double(mesh.positions.size()))
            fail(p.key("indices").index(i), "vertex index " + formatNumber(idx[i]) + " is out of range (" +
                                                 std::to_string(mesh.positions.size()) + " vertices)");
    for (std::size_t i = 0; i < idx.size(); i += 3)
        mesh.triangles.emplace_back(unsigned(idx[i]), unsigned(idx[i + 1]), unsigned(idx[i + 2]));
    if (o.contains("normals")) {
        const std::vector<double> n = readNumbers(o, "normals", p, 3, false);
        if (n.size() != pos.size())
            fail(p.key("normals"), "expected one normal per vertex (" + std::to_string(pos.size()) +
                                       " numbers), got " + std::to_string(n.size()) + " numbers");
        for (std::size_t i = 0; i < n.size(); i += 3) {
            const glm::vec3 v{float(n[i]), float(n[i + 1]), float(n[i + 2])};
            if (!(glm::length(v) > 0.0f)) fail(p.key("normals").index(i), "a normal must not be zero");
            mesh.normals.push_back(glm::normalize(v));
        }
    }
    if (o.contains("uvs")) {
        const std::vector<double> uv = readNumbers(o, "uvs", p, 2, false);
        if (uv.size() / 2 != mesh.positions.size())
            fail(p.key("uvs"), "expected one uv pair per vertex (" + std::to_string(2 * mesh.positions.size()) +
                                   " numbers), got " + std::to_string(uv.size()) + " numbers");
        for (std::size_t i = 0; i < uv.size(); i += 2) mesh.uvs.emplace_back(float(uv[i]), float(uv[i + 1]));
    }
    mesh.emissionSides = readEmissionSides(o, p, false);
    return mesh;
}

// One entry of "lights": its type first, then only the keys that type takes, then the checks
// between keys.
Light readLight(const Json& o, const JsonPath& p) {
    if (!o.is_object()) fail(p, "expected an object { \"type\": \"point\", ... }, got " + typeOf(o));
    const LightParamSpec& typeSpec = lightParameters().front();
    if (!o.contains("type")) fail(p, "a light needs \"type\" (point, spot or distant)");
    Light light;
    typeSpec.set(light, readValue(typeSpec, o["type"], p.key("type")));
    const std::vector<std::string_view> own = lightKeysOf(light.type);
    std::vector<std::string_view> all;
    for (const LightParamSpec& s : lightParameters()) all.push_back(s.name());
    for (const auto& [k, v] : o.items()) {
        (void)v;
        if (k == "type" || std::find(own.begin(), own.end(), k) != own.end()) continue;
        if (std::find(all.begin(), all.end(), k) != all.end())
            fail(p.key(k), inQuotes(k) + " does not apply to a " + std::string(typeSpec.enumName(int(light.type))) +
                               " light (its keys: " + joinNames(own) + ")", true);
        std::vector<std::string_view> known = own;
        known.insert(known.begin(), "type");
        failUnknownKey(p, k, known);
    }
    readMembers(o, p, lightParameters(), "lights[]", light, {"type"});
    if (o.contains("intensity") && o.contains("power"))
        fail(p.key("power"), "give either \"intensity\" or \"power\", not both", true);
    if (o.contains("direction") && !(glm::length(light.direction) > 0.0f && std::isfinite(glm::length(light.direction))))
        fail(p.key("direction"), "must be a non-zero direction, got " +
                                     formatValue(lightParameters()[2], light.direction));
    if (light.innerAngle > light.outerAngle)
        fail(p.key(o.contains("inner_angle") ? "inner_angle" : "outer_angle"),
             "inner_angle (" + formatNumber(light.innerAngle) + ") must not exceed outer_angle (" +
                 formatNumber(light.outerAngle) + ")");
    if (light.type == Light::Type::Spot && light.power > 0.0f && !(light.outerAngle > 0.0f))
        fail(p.key("power"), "a spot with outer_angle 0 has no cone to spread its power over; give intensity");
    return light;
}

} // namespace

void checkCamera(const Camera& c) {
    const JsonPath camera = JsonPath{}.key("camera");
    const glm::vec3 view = c.lookAt - c.position;
    const float distance = glm::length(view);
    if (!(distance > 0.0f))
        fail(camera.key("look_at"), "must differ from camera.position (both are " +
                                        formatValue(*findParameter("camera.position"), c.position) + ")");
    if (!std::isfinite(distance))
        fail(camera.key("look_at"), "is too far from camera.position (the distance overflows a float)");
    const float upLength = glm::length(c.up);
    if (!(upLength > 0.0f) || !std::isfinite(upLength))
        fail(camera.key("up"), "must be a non-zero direction, got " + formatValue(*findParameter("camera.up"), c.up));
    // |a x b| = sin(angle) for unit vectors; below 1e-4 (about 0.006 degrees) the basis degenerates.
    if (glm::length(glm::cross(view / distance, c.up / upLength)) < 1e-4f)
        fail(camera.key("up"), "is parallel to the view direction look_at - position = " +
                                   formatValue(*findParameter("camera.up"), view / distance) +
                                   "; choose an up direction across the view");
}

void readSkyMap(const Json& root, Scene& scene) {
    const JsonPath sky = JsonPath{}.key("sky");
    if (root.contains("sky") && root["sky"].is_object() && root["sky"].contains("map")) {
        const Json& m = root["sky"]["map"];
        if (!m.is_string() || m.get_ref<const std::string&>().empty())
            fail(sky.key("map"), "expected an image file name (a non-empty string), got " + typeOf(m));
        std::filesystem::path file = m.get<std::string>();
        if (file.is_relative()) file = scene.sourcePath.parent_path() / file;
        std::error_code ec;
        if (!std::filesystem::is_regular_file(file, ec))
            fail(sky.key("map"), "cannot read '" + file.string() + "': no such file");
        if (const auto problem = skyMapProblem(file)) fail(sky.key("map"), file.string() + ": " + *problem);
        scene.sky.map = file;
    }
    if (scene.sky.type == Sky::Type::Map && scene.sky.map.empty())
        fail(sky.key("type"), "'map' needs sky.map, an equirectangular .hdr or .exr image");
}

void buildScene(const Json& root, Scene& scene) {
    const JsonPath top;
    if (!root.is_object()) fail(top, "a scene file must be a JSON object { ... }, got " + typeOf(root));
    const std::vector<std::string_view> sections(std::begin(kSectionKeys), std::end(kSectionKeys));
    for (const auto& [k, v] : root.items()) {
        (void)v;
        if (std::find(sections.begin(), sections.end(), k) == sections.end())
            failUnknownKey(top, k, sections);
    }

    for (std::string_view section : {"camera", "render", "sky", "ao"}) {
        const std::string name(section);
        if (!root.contains(name)) continue;
        if (section == "sky") readMembers(root[name], top.key(name), sceneParameters(), section, scene, {"map"});
        else readMembers(root[name], top.key(name), sceneParameters(), section, scene);
    }
    readSkyMap(root, scene);
    // Asked for in so many words, adaptive sampling with stratified or zsobol is an error; by default
    // it simply stays off with them (adaptiveInEffect).
    const bool adaptiveAsked = root.contains("render") && root["render"].contains("adaptive") && scene.render.adaptive;
    if (adaptiveAsked && !adaptiveInEffect(scene.render))
        fail(top.key("render").key("adaptive"),
             "adaptive sampling needs render.sampler sobol or independent: stratified and zsobol lay out render.spp "
             "samples per pixel, and an adaptive pixel takes more");

    // Materials: a name -> properties map. Kept sorted by name so the order does not depend on the file.
    std::vector<Material> materials;
    if (root.contains("materials")) {
        const JsonPath p = top.key("materials");
        const Json& all = root["materials"];
        if (!all.is_object())
            fail(p, "expected an object { \"name\": { ... }, ... }, got " + typeOf(all));
        for (const auto& [name, m] : all.items()) {
            if (name.empty()) fail(p.key(name), "a material name must not be empty", true);
            Material mat;
            mat.name = name;
            readMembers(m, p.key(name), materialParameters(), "", mat, materialFileKeys());
            for (const TextureSlot& slot : textureSlots()) {
                if (m.contains(slot.key))
                    readTextureSlot(slot, m[std::string(slot.key)], p.key(name).key(slot.key),
                                    scene.sourcePath.parent_path(), scene.textures, mat);
            }
            materials.push_back(std::move(mat));
        }
    }
    std::vector<std::string_view> materialNames;
    for (const Material& m : materials) materialNames.push_back(m.name);
    const bool haveDefault = std::find(materialNames.begin(), materialNames.end(), kDefaultMaterial) !=
                             materialNames.end();

    // Objects.
    const JsonPath objectsPath = top.key("objects");
    if (!root.contains("objects"))
        fail(objectsPath, "a scene needs at least one object, and there is no \"objects\" array");
    const Json& objects = root["objects"];
    if (!objects.is_array()) fail(objectsPath, "expected an array [ { ... }, ... ], got " + typeOf(objects));
    if (objects.empty()) fail(objectsPath, "a scene needs at least one object, got an empty array");
    std::vector<PendingSphere> spheres;
    std::vector<PendingMesh> meshes;
    const std::filesystem::path sceneDir = scene.sourcePath.parent_path();
    const std::vector<std::string_view> types(std::begin(kObjectTypes), std::end(kObjectTypes));
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const JsonPath p = objectsPath.index(i);
        const Json& o = objects[i];
        if (!o.is_object()) fail(p, "expected an object { \"type\": \"sphere\", ... }, got " + typeOf(o));
        bool isMesh = false;
        if (o.contains("type")) {
            const Json& t = o["type"];
            if (!t.is_string()) fail(p.key("type"), "expected a string (" + joinNames(types) + "), got " + typeOf(t));
            const std::string& ts = t.get_ref<const std::string&>();
            if (std::find(types.begin(), types.end(), ts) == types.end())
                fail(p.key("type"), "unknown object type " + inQuotes(ts) + suggestion(ts, types, "known types"));
            isMesh = ts == "mesh";
        }
        std::string material = std::string(kDefaultMaterial);
        if (o.contains("material")) {
            const Json& m = o["material"];
            if (!m.is_string()) fail(p.key("material"), "expected a material name (a string), got " + typeOf(m));
            material = m.get<std::string>();
        }
        const bool known = std::find(materialNames.begin(), materialNames.end(), material) != materialNames.end();
        if (!known && material != kDefaultMaterial) {
            fail(p.key("material"), "unknown material " + inQuotes(material) +
                                        suggestion(material, materialNames, "defined materials"));
        }
        if (isMesh) {
            GltfAsset gltf;
            PendingMesh m{readMesh(o, p, sceneDir, &gltf), material, {}};
            readDisplacement(o, p, sceneDir, m.mesh);
            addGltfMaterials(std::move(gltf), o.contains("material"), m, scene);
            m.mesh.transform = readTransform(o, p);
            meshes.push_back(std::move(m));
            continue;
        }
        PendingSphere s;
        readMembers(o, p, sphereParameters(), "", s.sphere, {"type", "material", "transform"});
        s.sphere.transform = readTransform(o, p);
        const glm::vec3 sc = s.sphere.transform.scale;
        if (sc.x != sc.y || sc.x != sc.z)
            fail(p.key("transform").key("scale"), "a sphere needs a uniform scale (one number or three equal ones), got " +
                                                      formatValue(transformParameters().back(), sc));
        s.material = material;
        spheres.push_back(std::move(s));
    }

    // "default" is built in (albedo 0.8 grey) unless the file defines it.
    const bool needDefault =
        std::any_of(spheres.begin(), spheres.end(), [](const PendingSphere& s) { return s.material == kDefaultMaterial; }) ||
        std::any_of(meshes.begin(), meshes.end(), [](const PendingMesh& m) { return m.material == kDefaultMaterial; });
    if (needDefault && !haveDefault) {
        Material d;
        d.name = std::string(kDefaultMaterial);
        materials.push_back(d);
    }
    std::sort(materials.begin(), materials.end(),
              [](const Material& a, const Material& b) { return a.name < b.name; });
    std::map<std::string, int, std::less<>> indexOf;
    for (std::size_t i = 0; i < materials.size(); ++i) indexOf[materials[i].name] = static_cast<int>(i);

    scene.materials = std::move(materials);
    scene.spheres.clear();
    for (PendingSphere& s : spheres) {
        s.sphere.material = indexOf.at(s.material);
        scene.spheres.push_back(s.sphere);
    }
    scene.meshes.clear();
    for (PendingMesh& m : meshes) {
        m.mesh.material = indexOf.at(m.material);
        // glTF materials follow the file's own (sorted) ones; one copy per glTF file and material.
        const std::vector<int> gltfIndex = appendNew(scene.materials, m.gltfMaterials,
                                                     [](const Material& a, const Material& b) { return a.name == b.name; });
        for (int& t : m.mesh.triangleMaterials) t = t < 0 ? -1 : gltfIndex[std::size_t(t)];
        scene.meshes.push_back(std::move(m.mesh));
    }

    scene.lights.clear();
    if (root.contains("lights")) {
        const JsonPath lp = top.key("lights");
        const Json& lights = root["lights"];
        if (!lights.is_array()) fail(lp, "expected an array [ { \"type\": ... }, ... ], got " + typeOf(lights));
        if (lights.size() > std::size_t(kMaxLights))
            fail(lp.index(std::size_t(kMaxLights)), "a scene takes at most " + std::to_string(kMaxLights) + " lights");
        for (std::size_t i = 0; i < lights.size(); ++i) scene.lights.push_back(readLight(lights[i], lp.index(i)));
    }

    checkCamera(scene.camera);
}

} // namespace raylab::scenefmt
