#include "scene/scene_loader.h"

#include "scene/json_locator.h"
#include "scene/gltf_loader.h"
#include "scene/obj_loader.h"
#include "scene/parameters.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <utility>
#include <variant>

namespace raylab {
namespace {

// Parsed documents keep the file's key order, so that validation meets problems in reading order.
using Json = nlohmann::ordered_json;

constexpr std::string_view kDefaultMaterial = "default";
constexpr std::string_view kSectionKeys[] = {"camera", "render", "sky", "materials", "objects"};
constexpr std::string_view kObjectTypes[] = {"sphere", "mesh"};

// ------------------------------------------------------------------------------------------------
// Paths: a value's place in the document, shown as objects[2].radius and as JSON pointer.

struct Path {
    struct Segment {
        std::string token;
        bool index = false;
    };
    std::vector<Segment> segments;

    Path key(std::string_view k) const {
        Path p = *this;
        p.segments.push_back({std::string(k), false});
        return p;
    }
    Path index(std::size_t i) const {
        Path p = *this;
        p.segments.push_back({std::to_string(i), true});
        return p;
    }
    std::string pointer() const {
        std::string out;
        for (const Segment& s : segments) out += "/" + JsonLocator::escapeToken(s.token);
        return out;
    }
    std::string display() const {
        if (segments.empty()) return "(top level)";
        std::string out;
        for (const Segment& s : segments) {
            if (s.index) {
                out += "[" + s.token + "]";
            } else if (isPlainName(s.token)) {
                if (!out.empty()) out += ".";
                out += s.token;
            } else {
                out += "[" + Json(s.token).dump() + "]";  // quoted, e.g. materials["my lamp"]
            }
        }
        return out;
    }
    static bool isPlainName(std::string_view s) {
        if (s.empty()) return false;
        return std::all_of(s.begin(), s.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
        });
    }
};

// "in render", "at the top level": where a key was found, for unknown-key messages.
std::string inWhere(const Path& p) { return p.segments.empty() ? "at the top level" : "in " + p.display(); }

bool isPointerPrefix(std::string_view prefix, std::string_view pointer) {
    return pointer == prefix ||
           (pointer.size() > prefix.size() && pointer.substr(0, prefix.size()) == prefix &&
            pointer[prefix.size()] == '/');
}

// The first validation problem: thrown inside the validator, turned into a SceneError with a location.
struct Failure {
    Path path;
    std::string message;
    bool atKey = false;  // point at the member's key rather than its value (unknown/duplicate keys)
};

[[noreturn]] void fail(const Path& path, std::string message, bool atKey = false) {
    throw Failure{path, std::move(message), atKey};
}

std::string typeOf(const Json& v) {
    switch (v.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return "boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return "number";
    case Json::value_t::string: return "string";
    case Json::value_t::array: return "array";
    case Json::value_t::object: return "object";
    default: return "unsupported value";
    }
}

std::string inQuotes(std::string_view s) { return "'" + std::string(s) + "'"; }

std::string joinNames(const std::vector<std::string_view>& names) {
    std::string out;
    for (std::string_view n : names) {
        if (!out.empty()) out += ", ";
        out += n;
    }
    return out;
}

// "did you mean 'radius'?" when a candidate is close, else the full list.
std::string suggestion(std::string_view word, const std::vector<std::string_view>& candidates,
                       std::string_view listName) {
    const std::string_view best = closestMatch(word, candidates);
    if (!best.empty()) return "; did you mean " + inQuotes(best) + "?";
    if (candidates.empty()) return " (there are no " + std::string(listName) + ")";
    return " (" + std::string(listName) + ": " + joinNames(candidates) + ")";
}

// ------------------------------------------------------------------------------------------------
// JSON text -> document, with the byte offset of a syntax error. nlohmann reports number overflow
// (1e999) as an exception without position; its SAX interface gives the position, so we build the
// document through our own SAX handler.

struct ParseResult {
    Json doc;
    bool ok = false;
    std::size_t errorOffset = 0;
    std::string reason;                 // the parser's explanation
    std::optional<Path> errorPath;      // set for out-of-range numbers (known value position)
};

class DomBuilder : public nlohmann::json_sax<Json> {
public:
    ParseResult result;

    bool null() override { return add(Json(nullptr)); }
    bool boolean(bool v) override { return add(Json(v)); }
    bool number_integer(number_integer_t v) override { return add(Json(v)); }
    bool number_unsigned(number_unsigned_t v) override { return add(Json(v)); }
    bool number_float(number_float_t v, const string_t&) override { return add(Json(v)); }
    bool string(string_t& v) override { return add(Json(std::move(v))); }
    bool binary(binary_t& v) override { return add(Json::binary(std::move(v))); }
    bool start_object(std::size_t) override { return open(Json::object()); }
    bool key(string_t& k) override {
        stack_.back().key = k;
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(Json::array()); }
    bool end_array() override { return close(); }

    bool parse_error(std::size_t position, const std::string& lastToken,
                     const nlohmann::detail::exception& ex) override {
        result.ok = false;
        // `position` counts the characters read, so position - 1 is the offending character.
        result.errorOffset = position > 0 ? position - 1 : 0;
        if (ex.id == 406) {  // out_of_range.406: a number overflows a double (e.g. 1e999)
            result.errorOffset = position >= lastToken.size() ? position - lastToken.size() : 0;
            result.reason = "must be finite, got " + lastToken + " (too large for a double)";
            result.errorPath = currentPath();
        } else {
            result.reason = stripPrefix(ex.what());
        }
        return false;
    }

private:
    struct Level {
        Json* container;
        std::string key;  // objects: the key of the value that comes next
    };

    Json* place(Json&& v) {
        if (stack_.empty()) {
            result.doc = std::move(v);
            return &result.doc;
        }
        Level& top = stack_.back();
        if (top.container->is_array()) {
            top.container->push_back(std::move(v));
            return &top.container->back();
        }
        Json& slot = (*top.container)[top.key];
        slot = std::move(v);
        return &slot;
    }
    bool add(Json&& v) {
        place(std::move(v));
        return true;
    }
    bool open(Json&& v) {
        stack_.push_back(Level{place(std::move(v)), {}});
        return true;
    }
    bool close() {
        stack_.pop_back();
        return true;
    }
    Path currentPath() const {
        // Enclosing arrays already hold the element being filled (the last one); the innermost
        // container has not received the offending value yet.
        Path p;
        for (std::size_t i = 0; i < stack_.size(); ++i) {
            const Json& c = *stack_[i].container;
            if (!c.is_array()) p = p.key(stack_[i].key);
            else p = p.index(i + 1 < stack_.size() ? c.size() - 1 : c.size());
        }
        return p;
    }
    // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ..." -> "syntax error ..."
    static std::string stripPrefix(std::string_view what) {
        if (auto bracket = what.find("] "); bracket != std::string_view::npos && what.front() == '[')
            what.remove_prefix(bracket + 2);
        if (what.starts_with("parse error")) {
            if (auto colon = what.find(": "); colon != std::string_view::npos) what.remove_prefix(colon + 2);
        }
        return std::string(what);
    }

    std::vector<Level> stack_;
};

ParseResult parseJson(std::string_view text) {
    DomBuilder builder;
    builder.result.ok = true;
    const bool ok = Json::sax_parse(text.begin(), text.end(), &builder, nlohmann::json::input_format_t::json,
                                    /*strict=*/true, /*ignore_comments=*/true);
    builder.result.ok = ok && builder.result.ok;
    return std::move(builder.result);
}

// ------------------------------------------------------------------------------------------------
// Validation: document -> Scene, through the parameter tables.

double numberOf(const Json& v) {
    if (v.is_number_unsigned()) return static_cast<double>(v.get<std::uint64_t>());
    if (v.is_number_integer()) return static_cast<double>(v.get<std::int64_t>());
    return v.get<double>();
}

double readScalar(const ValueSpec& spec, const Json& v, const Path& p) {
    if (!v.is_number()) {
        const bool integral = spec.type == ParamType::Int || spec.type == ParamType::UInt;
        fail(p, std::string(integral ? "expected an integer" : "expected a number") + ", got " + typeOf(v));
    }
    const double d = numberOf(v);
    if (auto err = checkScalar(spec, d)) fail(p, *err);
    return d;
}

ParamValue readValue(const ValueSpec& spec, const Json& v, const Path& p) {
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
void readMembers(const Json& obj, const Path& p, const std::vector<FieldSpec<Target>>& table,
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
            fail(p.key(k), "unknown key " + inQuotes(k) + " " + inWhere(p) + suggestion(k, known, "known keys"),
                 true);
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

// An image file for a material (relative to the scene's directory), loaded once per path.
int readTexture(const Json& v, const Path& p, const std::filesystem::path& sceneDir, std::vector<Texture>& textures,
                std::string& given, bool linearData = false) {
    if (!v.is_string() || v.get_ref<const std::string&>().empty())
        fail(p, "expected the path of an image file (a string), got " + typeOf(v));
    given = v.get<std::string>();
    const std::filesystem::path path =
        std::filesystem::path(given).is_absolute() ? std::filesystem::path(given) : sceneDir / given;
    const std::string key = (linearData ? "linear:" : "srgb:") + given;   // one file, two decodings
    for (std::size_t i = 0; i < textures.size(); ++i)
        if (textures[i].file == key) return int(i);
    if (!std::filesystem::is_regular_file(path)) fail(p, path.string() + ": cannot read: no such file");
    try {
        Texture t = loadTexture(path, linearData);
        t.file = key;
        textures.push_back(std::move(t));
    } catch (const TextureError& e) {
        fail(p, e.what());
    }
    return int(textures.size() - 1);
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
    std::vector<int> textureIndex;
    for (Texture& t : gltf.textures) {
        const auto known = std::find_if(scene.textures.begin(), scene.textures.end(),
                                        [&t](const Texture& x) { return x.file == t.file; });
        textureIndex.push_back(int(known - scene.textures.begin()));
        if (known == scene.textures.end()) scene.textures.push_back(std::move(t));
    }
    auto remap = [&textureIndex](int& i) { i = i < 0 ? -1 : textureIndex[std::size_t(i)]; };
    for (Material& m : gltf.materials) {
        m.name = pending.mesh.file + "#" + m.name;
        remap(m.albedoTextureIndex);
        remap(m.normalTextureIndex);
        remap(m.roughnessTextureIndex);
        remap(m.metallicTextureIndex);
        remap(m.emissionTextureIndex);
        m.fromGltf = true;
    }
    pending.gltfMaterials = std::move(gltf.materials);
}

// "transform": { "translation", "rotation", "scale" }; scale may be one number for all axes.
Transform readTransform(const Json& o, const Path& p) {
    Transform t;
    if (!o.contains("transform")) return t;
    const Path tp = p.key("transform");
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
std::vector<double> readNumbers(const Json& o, const char* key, const Path& p, std::size_t group,
                                bool integers) {
    const Path kp = p.key(key);
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

// A mesh object: inline arrays, or "file" (OBJ, relative to the scene file's directory).
Mesh readMesh(const Json& o, const Path& p, const std::filesystem::path& sceneDir, GltfAsset* gltf) {
    std::vector<std::string_view> known = {"type", "material", "transform"};
    for (std::string_view k : meshKeys()) known.push_back(k);
    for (const auto& [k, v] : o.items()) {
        (void)v;
        if (std::find(known.begin(), known.end(), k) == known.end())
            fail(p.key(k), "unknown key " + inQuotes(k) + " " + inWhere(p) + suggestion(k, known, "known keys"), true);
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
            const glm::vec3 v(float(n[i]), float(n[i + 1]), float(n[i + 2]));
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
    return mesh;
}

void checkCamera(const Camera& c) {
    const Path camera = Path{}.key("camera");
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

// sky.map: a file name, relative to the scene file's directory; it must exist. sky.type "map"
// needs one.
void readSkyMap(const Json& root, Scene& scene) {
    const Path sky = Path{}.key("sky");
    if (root.contains("sky") && root["sky"].is_object() && root["sky"].contains("map")) {
        const Json& m = root["sky"]["map"];
        if (!m.is_string() || m.get_ref<const std::string&>().empty())
            fail(sky.key("map"), "expected an image file name (a non-empty string), got " + typeOf(m));
        std::filesystem::path file = m.get<std::string>();
        if (file.is_relative()) file = scene.sourcePath.parent_path() / file;
        std::error_code ec;
        if (!std::filesystem::is_regular_file(file, ec))
            fail(sky.key("map"), "cannot read " + inQuotes(file.string()) + ": no such file");
        scene.sky.map = file;
    }
    if (scene.sky.type == Sky::Type::Map && scene.sky.map.empty())
        fail(sky.key("type"), "'map' needs sky.map, an equirectangular .hdr or .exr image");
}

void validate(const Json& root, Scene& scene) {
    const Path top;
    if (!root.is_object()) fail(top, "a scene file must be a JSON object { ... }, got " + typeOf(root));
    const std::vector<std::string_view> sections(std::begin(kSectionKeys), std::end(kSectionKeys));
    for (const auto& [k, v] : root.items()) {
        (void)v;
        if (std::find(sections.begin(), sections.end(), k) == sections.end())
            fail(top.key(k), "unknown key " + inQuotes(k) + " " + inWhere(top) + suggestion(k, sections, "known keys"),
                 true);
    }

    for (std::string_view section : {"camera", "render", "sky"}) {
        const std::string name(section);
        if (!root.contains(name)) continue;
        if (section == "sky") readMembers(root[name], top.key(name), sceneParameters(), section, scene, {"map"});
        else readMembers(root[name], top.key(name), sceneParameters(), section, scene);
    }
    readSkyMap(root, scene);

    // Materials: a name -> properties map. Kept sorted by name so the order does not depend on the file.
    std::vector<Material> materials;
    if (root.contains("materials")) {
        const Path p = top.key("materials");
        const Json& all = root["materials"];
        if (!all.is_object())
            fail(p, "expected an object { \"name\": { ... }, ... }, got " + typeOf(all));
        for (const auto& [name, m] : all.items()) {
            if (name.empty()) fail(p.key(name), "a material name must not be empty", true);
            Material mat;
            mat.name = name;
            readMembers(m, p.key(name), materialParameters(), "", mat, materialFileKeys());
            if (m.contains("albedo_texture"))
                mat.albedoTextureIndex = readTexture(m["albedo_texture"], p.key(name).key("albedo_texture"),
                                                     scene.sourcePath.parent_path(), scene.textures,
                                                     mat.albedoTexture);
            if (m.contains("normal_texture"))
                mat.normalTextureIndex = readTexture(m["normal_texture"], p.key(name).key("normal_texture"),
                                                     scene.sourcePath.parent_path(), scene.textures,
                                                     mat.normalTexture, true);
            if (m.contains("roughness_texture"))
                mat.roughnessTextureIndex = readTexture(m["roughness_texture"], p.key(name).key("roughness_texture"),
                                                        scene.sourcePath.parent_path(), scene.textures,
                                                        mat.roughnessTexture, true);
            if (m.contains("metallic_texture"))
                mat.metallicTextureIndex = readTexture(m["metallic_texture"], p.key(name).key("metallic_texture"),
                                                       scene.sourcePath.parent_path(), scene.textures,
                                                       mat.metallicTexture, true);
            if (m.contains("emission_texture"))
                mat.emissionTextureIndex = readTexture(m["emission_texture"], p.key(name).key("emission_texture"),
                                                       scene.sourcePath.parent_path(), scene.textures,
                                                       mat.emissionTexture);
            materials.push_back(std::move(mat));
        }
    }
    std::vector<std::string_view> materialNames;
    for (const Material& m : materials) materialNames.push_back(m.name);
    const bool haveDefault = std::find(materialNames.begin(), materialNames.end(), kDefaultMaterial) !=
                             materialNames.end();

    // Objects.
    const Path objectsPath = top.key("objects");
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
        const Path p = objectsPath.index(i);
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
        std::vector<int> gltfIndex;
        for (Material& g : m.gltfMaterials) {
            const auto known = std::find_if(scene.materials.begin(), scene.materials.end(),
                                            [&g](const Material& x) { return x.name == g.name; });
            gltfIndex.push_back(int(known - scene.materials.begin()));
            if (known == scene.materials.end()) scene.materials.push_back(std::move(g));
        }
        for (int& t : m.mesh.triangleMaterials) t = t < 0 ? -1 : gltfIndex[std::size_t(t)];
        scene.meshes.push_back(std::move(m.mesh));
    }

    checkCamera(scene.camera);
}

// ------------------------------------------------------------------------------------------------
// Overrides ("--set KEY=VALUE").

struct AppliedOverride {
    std::string pointer;  // of the value it wrote
    std::string text;     // as given, for messages
};

std::string overridePrefix(const std::string& text) { return "--set " + text + ": error: "; }

bool looksLikeJson(std::string_view v) {
    const auto first = v.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return false;
    const char c = v[first];
    return c == '[' || c == '{' || c == '"' || c == '-' || std::isdigit(static_cast<unsigned char>(c));
}

AppliedOverride applyOverride(Json& root, const std::string& text) {
    auto error = [&text](const Path* at, const std::string& what) -> SceneError {
        return SceneError(overridePrefix(text) + (at ? at->display() + ": " : std::string()) + what);
    };
    const auto eq = text.find('=');
    if (eq == std::string::npos) throw error(nullptr, "expected KEY=VALUE, e.g. render.spp=256");
    const std::string key = text.substr(0, eq);
    const std::string valueText = text.substr(eq + 1);

    std::vector<std::string> segments;
    for (std::size_t start = 0;;) {
        const auto dot = key.find('.', start);
        segments.push_back(key.substr(start, dot == std::string::npos ? std::string::npos : dot - start));
        if (dot == std::string::npos) break;
        start = dot + 1;
    }
    for (const std::string& s : segments)
        if (s.empty()) throw error(nullptr, "the key '" + key + "' has an empty part; write it like render.spp");

    Json value;
    ParseResult parsed = parseJson(valueText);
    if (parsed.ok) {
        value = std::move(parsed.doc);
    } else if (looksLikeJson(valueText)) {
        throw error(nullptr, "the value is not valid JSON: " + parsed.reason);
    } else {
        value = valueText;  // a bare word, e.g. sky.type=constant
    }

    if (!root.is_object()) throw error(nullptr, "the scene file's top level is not an object");
    Json* cur = &root;
    Path path;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const std::string& seg = segments[i];
        const bool last = i + 1 == segments.size();
        if (cur->is_null()) *cur = Json::object();
        if (cur->is_object()) {
            path = path.key(seg);
            if (!last && !cur->contains(seg)) (*cur)[seg] = Json::object();
            cur = &(*cur)[seg];
        } else if (cur->is_array()) {
            const bool digits = seg.size() < 10 &&
                                std::all_of(seg.begin(), seg.end(), [](char c) { return c >= '0' && c <= '9'; });
            if (!digits) throw error(&path, "is an array; expected an element index, got '" + seg + "'");
            const std::size_t index = std::stoul(seg);
            if (index >= cur->size()) {
                const Path at = path.index(index);
                const std::size_t n = cur->size();
                throw error(&at, "index " + seg + " is past the end of " + path.display() + " (" +
                                     std::to_string(n) + (n == 1 ? " element)" : " elements)"));
            }
            path = path.index(index);
            cur = &(*cur)[index];
        } else {
            throw error(&path, "is a " + typeOf(*cur) + ", so it cannot contain '" + seg + "'");
        }
    }
    *cur = std::move(value);
    return AppliedOverride{path.pointer(), text};
}

// Rebuilds a Path (with array/key distinction) from a JSON pointer by walking the document.
Path pathFromPointer(const Json& doc, std::string_view pointer) {
    Path p;
    const Json* cur = &doc;
    std::size_t pos = 0;
    while (pos < pointer.size()) {
        const std::size_t next = pointer.find('/', pos + 1);
        const std::string_view raw =
            pointer.substr(pos + 1, next == std::string_view::npos ? std::string_view::npos : next - pos - 1);
        std::string token;  // RFC 6901 unescaping: "~1" -> '/', "~0" -> '~'
        for (std::size_t i = 0; i < raw.size(); ++i) {
            if (raw[i] == '~' && i + 1 < raw.size()) {
                token += raw[i + 1] == '1' ? '/' : '~';
                ++i;
            } else {
                token += raw[i];
            }
        }
        if (cur && cur->is_array()) {
            const std::size_t index = std::stoul(token);
            p = p.index(index);
            cur = index < cur->size() ? &(*cur)[index] : nullptr;
        } else {
            p = p.key(token);
            cur = (cur && cur->is_object() && cur->contains(token)) ? &(*cur)[token] : nullptr;
        }
        if (next == std::string_view::npos) break;
        pos = next;
    }
    return p;
}

std::string fileLocation(const std::string& fileName, SourcePos pos) {
    return fileName + ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column) + ": error: ";
}

// Formats a validation failure: at the override that wrote (or created) the value, else at the value
// (or key) in the file, else at the nearest enclosing value that is in the file.
std::string describeFailure(const Failure& f, const std::string& fileName, const JsonLocator& locator,
                            const std::vector<AppliedOverride>& overrides) {
    const std::string pointer = f.path.pointer();
    const std::string tail = f.path.display() + ": " + f.message;
    for (auto it = overrides.rbegin(); it != overrides.rend(); ++it)
        if (isPointerPrefix(it->pointer, pointer)) return overridePrefix(it->text) + tail;
    if (const ValueLocation* loc = locator.find(pointer))
        return fileLocation(fileName, f.atKey && loc->key.valid() ? loc->key : loc->value) + tail;
    for (auto it = overrides.rbegin(); it != overrides.rend(); ++it)
        if (isPointerPrefix(pointer, it->pointer)) return overridePrefix(it->text) + tail;
    // Cross-field checks (camera.up against camera.position) blame a sibling set by an override.
    const std::string parentPointer = pointer.substr(0, pointer.rfind('/'));
    for (auto it = overrides.rbegin(); it != overrides.rend(); ++it)
        if (!pointer.empty() && it->pointer.substr(0, it->pointer.rfind('/')) == parentPointer)
            return overridePrefix(it->text) + tail;
    Path parent = f.path;
    while (!parent.segments.empty()) {
        parent.segments.pop_back();
        if (const ValueLocation* loc = locator.find(parent.pointer())) return fileLocation(fileName, loc->value) + tail;
    }
    return fileLocation(fileName, SourcePos{1, 1}) + tail;
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

nlohmann::json meshJson(const Mesh& m, const std::string& material) {
    nlohmann::json o = nlohmann::json::object();
    o["type"] = "mesh";
    if (!m.file.empty()) {
        o["file"] = m.file;
    } else {
        auto flat = [](const auto& items, int n) {
            nlohmann::json a = nlohmann::json::array();
            for (const auto& v : items)
                for (int k = 0; k < n; ++k) a.push_back(v[k]);
            return a;
        };
        o["positions"] = flat(m.positions, 3);
        o["indices"] = flat(m.triangles, 3);
        if (!m.normals.empty()) o["normals"] = flat(m.normals, 3);
        if (!m.uvs.empty()) o["uvs"] = flat(m.uvs, 2);
    }
    o["transform"] = transformJson(m.transform);
    if (m.triangleMaterials.empty()) o["material"] = material;   // else the glTF file's materials
    return o;
}

} // namespace

Scene parseScene(std::string_view text, const std::string& fileName, const std::vector<std::string>& overrides) {
    ParseResult parsed = parseJson(text);
    const JsonLocator locator(text);
    if (!parsed.ok) {
        const std::string where = fileLocation(fileName, locator.position(parsed.errorOffset));
        if (parsed.errorPath) throw SceneError(where + parsed.errorPath->display() + ": " + parsed.reason);
        throw SceneError(where + parsed.reason);
    }
    Json& doc = parsed.doc;
    if (!locator.duplicates().empty()) {
        const JsonLocator::Duplicate& d = locator.duplicates().front();
        const Path p = pathFromPointer(doc, d.pointer);
        throw SceneError(fileLocation(fileName, d.second) + p.display() + ": duplicate key " +
                         inQuotes(p.segments.back().token) + " (first given at line " + std::to_string(d.first.line) +
                         ", column " + std::to_string(d.first.column) + ")");
    }

    std::vector<AppliedOverride> applied;
    for (const std::string& o : overrides) applied.push_back(applyOverride(doc, o));

    Scene scene;
    scene.sourcePath = fileName;
    try {
        validate(doc, scene);
    } catch (const Failure& f) {
        throw SceneError(describeFailure(f, fileName, locator, applied));
    }
    return scene;
}

Scene loadScene(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
    const std::string name = file.string();
    errno = 0;
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(file.c_str(), "rb"), &std::fclose);
    if (!f) throw SceneError(name + ": error: cannot read: " + std::strerror(errno));
    std::string text;
    char buffer[65536];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, f.get())) > 0) text.append(buffer, n);
    if (std::ferror(f.get())) {
        const int err = errno != 0 ? errno : EIO;
        throw SceneError(name + ": error: cannot read: " + std::strerror(err));
    }
    Scene scene = parseScene(text, name, overrides);
    scene.sourcePath = file;
    return scene;
}

nlohmann::json sceneToJson(const Scene& scene) {
    nlohmann::json j = nlohmann::json::object();
    for (const ParamSpec& spec : sceneParameters())
        j[std::string(spec.section())][std::string(spec.name())] = valueJson(spec, scene);

    nlohmann::json materials = nlohmann::json::object();
    for (const Material& m : scene.materials) {
        if (m.fromGltf) continue;   // read again from the mesh's file
        nlohmann::json mj = nlohmann::json::object();
        for (const MaterialParamSpec& spec : materialParameters()) mj[std::string(spec.key)] = valueJson(spec, m);
        if (!m.albedoTexture.empty()) mj["albedo_texture"] = m.albedoTexture;
        if (!m.normalTexture.empty()) mj["normal_texture"] = m.normalTexture;
        if (!m.roughnessTexture.empty()) mj["roughness_texture"] = m.roughnessTexture;
        if (!m.metallicTexture.empty()) mj["metallic_texture"] = m.metallicTexture;
        if (!m.emissionTexture.empty()) mj["emission_texture"] = m.emissionTexture;
        materials[m.name] = mj;
    }
    j["materials"] = materials;
    if (!scene.sky.map.empty()) j["sky"]["map"] = scene.sky.map.string();

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
    return j;
}

} // namespace raylab
