#pragma once
// The parameter table: one entry per scalar/vector key of the scene file's "camera", "render",
// "sky" and "ao" sections (plus small tables for the per-material and per-sphere keys). Each entry knows its
// type, range, unit, one-line help and what a change implies for a running render, and reads and
// writes the matching Scene field. The loader validates through it; a UI can build widgets from it
// and scenes/FORMAT.md documents it (a test checks that every key appears there).
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace raylab {

enum class ParamType {
    Int,    // 32-bit signed integer (JSON numbers with a fractional part are rejected)
    UInt,   // 32-bit unsigned integer
    Float,  // finite real number (stored as float or double)
    Vec3,   // [x, y, z], finite
    Rgb,    // [r, g, b] or a single number meaning grey; bounds apply per channel
    Enum,   // one of a fixed set of names
    Bool,   // JSON true or false (stored as 0 / 1 in ParamValue)
};

// What a change of the parameter implies for an interactive renderer, cheapest first.
enum class Trigger {
    Redisplay,          // accumulated samples stay valid: only re-run display / stop condition
    ResetAccumulation,  // uniforms change: restart accumulation from sample 0
    MoveObjects,        // objects moved: rebuild only the top-level BVH (the meshes' BVHs stay), restart
    UpdateMaterials,    // material values: re-upload materials and lights (geometry stays), restart
    RecompileShader,    // compile-time shader constants change (render.nee)
    ReloadScene,        // scene buffers or image sizes change: re-upload, reallocate, restart
};

struct Bound {
    double value = 0.0;
    bool inclusive = true;
};

struct EnumName {
    std::string_view name;
    int value = 0;        // the enumerator, as int
    bool alias = false;   // accepted on input, never written (e.g. "none" for "clamp")
};

// Int, UInt, Enum and Bool values are std::int64_t, Float is double, Vec3 and Rgb are glm::vec3.
using ParamValue = std::variant<std::int64_t, double, glm::vec3>;

// Everything about a parameter except how to reach its field.
struct ValueSpec {
    std::string_view key;            // "render.spp" (scene table) or "albedo" (per-item tables)
    ParamType type = ParamType::Float;
    std::optional<Bound> min;        // per component for Vec3/Rgb
    std::optional<Bound> max;
    std::vector<EnumName> enumNames; // Enum only; canonical names first
    std::string_view unit;           // "" when dimensionless
    std::string_view help;           // one line
    Trigger trigger = Trigger::ResetAccumulation;

    std::string_view section() const;  // "render" for "render.spp", "" for per-item keys
    std::string_view name() const;     // "spp" for "render.spp"
    const EnumName* findEnum(std::string_view name) const;   // nullptr when unknown
    std::string_view enumName(std::int64_t value) const;     // canonical name, "" when unknown
};

// A ValueSpec plus accessors on the object that holds the field (Scene, Material or Sphere).
template <class Target>
struct FieldSpec : ValueSpec {
    std::function<ParamValue(const Target&)> get;
    std::function<void(Target&, const ParamValue&)> set;  // value must have passed checkValue
    ParamValue defaultValue() const { return get(Target{}); }  // the default is whatever scene.h says
};

using ParamSpec = FieldSpec<Scene>;
using MaterialParamSpec = FieldSpec<Material>;
using SphereParamSpec = FieldSpec<Sphere>;
using TransformParamSpec = FieldSpec<Transform>;
using LightParamSpec = FieldSpec<Light>;
using DisplacementParamSpec = FieldSpec<MeshDisplacement>;

// camera.*, render.*, sky.*, ao.* in file-format order.
const std::vector<ParamSpec>& sceneParameters();
// Lookup by dotted key ("render.spp"); nullptr when there is no such parameter.
const ParamSpec* findParameter(std::string_view dottedKey);
// Keys of one entry of "materials" (albedo, emission, strength).
const std::vector<MaterialParamSpec>& materialParameters();
// Keys of a sphere in "objects" besides "type" and "material" (center, radius).
const std::vector<SphereParamSpec>& sphereParameters();
// Keys of an object's "transform" (transform.translation, transform.rotation, transform.scale).
const std::vector<TransformParamSpec>& transformParameters();
// Keys of an entry of "lights", as "lights[].position" (section "lights[]"), type first.
const std::vector<LightParamSpec>& lightParameters();
// The keys (names) a light of that type takes besides "type".
std::vector<std::string_view> lightKeysOf(Light::Type type);
// Keys of a mesh object's displacement besides its texture (displacement_scale, displacement_subdivision).
const std::vector<DisplacementParamSpec>& displacementParameters();
// Keys of a mesh object that the loader reads itself (arrays, the OBJ path, the displacement
// texture), for FORMAT.md.
const std::vector<std::string_view>& meshKeys();
// Keys of a material that name files (image textures), read by the loader itself.
const std::vector<std::string_view>& materialFileKeys();

// One image texture of a material: its key, the Material fields that hold the file as written and
// its index into Scene::textures, and whether the image is data (linear) rather than sRGB colour.
struct TextureSlot {
    std::string_view key;             // "albedo_texture"
    std::string Material::*file;
    int Material::*index;
    bool linearData = false;
};
// The slots in materialFileKeys() order.
const std::vector<TextureSlot>& textureSlots();

// Where a key that names a file sits in a scene document.
enum class PathScope {
    Scene,      // a section's key: "sky.map"
    Material,   // a key of each entry of "materials": "albedo_texture"
    Object,     // a key of each entry of "objects": "file"
};

// A key whose value is a file path, read relative to the scene file's directory (unless absolute);
// a saved scene writes it relative to the saved file's directory.
struct PathKey {
    PathScope scope = PathScope::Scene;
    std::string_view key;
};
// sky.map, the texture slots, a mesh's file.
const std::vector<PathKey>& pathKeys();

// Range/finiteness check of one number (one component for Vec3/Rgb). Returns the complaint without
// location, e.g. "must be > 0, got -1", or nullopt when the value is acceptable. Integer types also
// check that the value is whole and fits 32 bits.
std::optional<std::string> checkScalar(const ValueSpec& spec, double value);
// Same for a whole value of the spec's type (Vec3/Rgb name the offending component).
std::optional<std::string> checkValue(const ValueSpec& spec, const ParamValue& value);

// Text forms, as used in messages and in scenes/FORMAT.md.
std::string formatNumber(double value);                              // shortest form: 0.5, 1e+30, 64
std::string formatValue(const ValueSpec& spec, const ParamValue& value); // 64, [0, 1, 6], aces
std::string describeRange(const ValueSpec& spec);   // "[1, 16384]", "(0, 180)", ">= 0", "any"
std::string_view typeName(ParamType type);          // "int", "uint", "float", "vec3", "rgb", "enum"
std::string_view triggerName(Trigger trigger);      // "redisplay", "reset accumulation", ...

// Levenshtein edit distance (insert, delete, substitute, each cost 1), used for "did you mean".
std::size_t editDistance(std::string_view a, std::string_view b);
// The candidate closest to `word` if it is close enough to be a plausible typo, else "".
std::string_view closestMatch(std::string_view word, const std::vector<std::string_view>& candidates);

} // namespace raylab
