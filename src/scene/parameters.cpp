#include "scene/parameters.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>

namespace raylab {
namespace {

constexpr double kIntMin = static_cast<double>(std::numeric_limits<std::int32_t>::min());
constexpr double kIntMax = static_cast<double>(std::numeric_limits<std::int32_t>::max());
constexpr double kUIntMax = static_cast<double>(std::numeric_limits<std::uint32_t>::max());
constexpr double kFloatMax = static_cast<double>(std::numeric_limits<float>::max());

template <class Field>
ParamValue toParam(const Field& field) {
    if constexpr (std::is_same_v<Field, glm::vec3>) {
        return field;
    } else if constexpr (std::is_enum_v<Field>) {
        return static_cast<std::int64_t>(static_cast<int>(field));
    } else if constexpr (std::is_floating_point_v<Field>) {
        return static_cast<double>(field);
    } else {
        static_assert(std::is_integral_v<Field>);
        return static_cast<std::int64_t>(field);
    }
}

template <class Field>
void fromParam(const ParamValue& value, Field& field) {
    if constexpr (std::is_same_v<Field, glm::vec3>) {
        field = std::get<glm::vec3>(value);
    } else if constexpr (std::is_enum_v<Field>) {
        field = static_cast<Field>(static_cast<int>(std::get<std::int64_t>(value)));
    } else if constexpr (std::is_floating_point_v<Field>) {
        field = static_cast<Field>(std::get<double>(value));
    } else {
        field = static_cast<Field>(std::get<std::int64_t>(value));
    }
}

// `ref` is a generic lambda returning a reference to the field, used for both get and set.
template <class Target, class Ref>
FieldSpec<Target> makeField(ValueSpec spec, Ref ref) {
    FieldSpec<Target> f;
    static_cast<ValueSpec&>(f) = std::move(spec);
    f.get = [ref](const Target& t) -> ParamValue { return toParam(ref(t)); };
    f.set = [ref](Target& t, const ParamValue& v) { fromParam(v, ref(t)); };
    return f;
}

// Positional builder (GCC 12 warns about designated initialisers that leave members out).
ValueSpec spec(std::string_view key, ParamType type, std::optional<Bound> lo, std::optional<Bound> hi,
               std::string_view unit, std::string_view help, Trigger trigger,
               std::vector<EnumName> names = {}) {
    ValueSpec v;
    v.key = key;
    v.type = type;
    v.min = lo;
    v.max = hi;
    v.enumNames = std::move(names);
    v.unit = unit;
    v.help = help;
    v.trigger = trigger;
    return v;
}
constexpr std::nullopt_t kAny = std::nullopt;

Bound atLeast(double v) { return Bound{v, true}; }
Bound above(double v) { return Bound{v, false}; }
Bound atMost(double v) { return Bound{v, true}; }
Bound below(double v) { return Bound{v, false}; }

std::vector<ParamSpec> buildSceneTable() {
    using T = ParamType;
    using G = Trigger;
    std::vector<ParamSpec> t;
    auto add = [&t](ValueSpec v, auto ref) { t.push_back(makeField<Scene>(std::move(v), ref)); };

    // --- camera ---
    add(spec("camera.position", T::Vec3, kAny, kAny, "world units", "Eye point.", G::ResetAccumulation),
        [](auto& s) -> auto& { return s.camera.position; });
    add(spec("camera.look_at", T::Vec3, kAny, kAny, "world units",
             "Point the centre of the image looks at; must differ from position.", G::ResetAccumulation),
        [](auto& s) -> auto& { return s.camera.lookAt; });
    add(spec("camera.up", T::Vec3, kAny, kAny, "direction",
             "Approximate up direction (any length); must not be parallel to look_at - position.",
             G::ResetAccumulation),
        [](auto& s) -> auto& { return s.camera.up; });
    add(spec("camera.fov", T::Float, above(0), below(180), "degrees", "Vertical field of view.",
             G::ResetAccumulation),
        [](auto& s) -> auto& { return s.camera.fovY; });
    add(spec("camera.aperture", T::Float, atLeast(0), kAny, "world units",
             "Lens radius of the thin-lens camera; 0 = pinhole (everything sharp).", G::ResetAccumulation),
        [](auto& s) -> auto& { return s.camera.aperture; });
    add(spec("camera.focus_distance", T::Float, atLeast(0), kAny, "world units",
             "Distance along the view axis that is in focus; 0 = the distance to look_at.",
             G::ResetAccumulation),
        [](auto& s) -> auto& { return s.camera.focusDistance; });

    // --- render ---
    const std::vector<EnumName> samplerNames = {{"independent", static_cast<int>(SamplerKind::Independent)},
                                                {"stratified", static_cast<int>(SamplerKind::Stratified)},
                                                {"sobol", static_cast<int>(SamplerKind::Sobol)},
                                                {"zsobol", static_cast<int>(SamplerKind::ZSobol)}};
    add(spec("render.width", T::Int, atLeast(1), atMost(16384), "pixels",
             "Image width (changing it reallocates the image).", G::ReloadScene),
        [](auto& s) -> auto& { return s.render.width; });
    add(spec("render.height", T::Int, atLeast(1), atMost(16384), "pixels",
             "Image height (changing it reallocates the image).", G::ReloadScene),
        [](auto& s) -> auto& { return s.render.height; });
    add(spec("render.rpp", T::Int, atLeast(1), atMost(1024), "samples",
             "Samples per pixel traced in one pass (drawn at most 16 at a time, up to 64 where the scene's loops are bounded: llvmpipe's loop limit, README).", G::ResetAccumulation),
        [](auto& s) -> auto& { return s.render.rpp; });
    add(spec("render.spp", T::Int, atLeast(1), kAny, "samples",
             "Target samples per pixel; the render stops when reached.", G::Redisplay),
        [](auto& s) -> auto& { return s.render.spp; });
    add(spec("render.time", T::Float, atLeast(0), kAny, "seconds",
             "Time budget, 0 = unlimited; the render stops at spp or time, whichever comes first.",
             G::Redisplay),
        [](auto& s) -> auto& { return s.render.timeBudget; });
    add(spec("render.max_bounces", T::Int, atLeast(0), atMost(1024), "bounces",
             "Scattering events per path; 0 shows only emitters and sky.", G::ResetAccumulation),
        [](auto& s) -> auto& { return s.render.maxBounces; });
    add(spec("render.rr_depth", T::Int, atLeast(0), kAny, "bounces",
             "Russian roulette starts after this many bounces.", G::ResetAccumulation),
        [](auto& s) -> auto& { return s.render.rrDepth; });
    add(spec("render.seed", T::UInt, atLeast(0), atMost(kUIntMax), "",
             "Sampler seed: same seed, same image bit for bit.", G::ResetAccumulation),
        [](auto& s) -> auto& { return s.render.seed; });
    add(spec("render.nee", T::Bool, kAny, kAny, "",
             "Next-event estimation: each bounce also samples emissive spheres, emissive triangles and the sky directly.",
             G::RecompileShader),
        [](auto& s) -> auto& { return s.render.nee; });
    add(spec("render.mis", T::Bool, kAny, kAny, "",
             "With nee: combine light and BSDF samples by multiple importance sampling (power heuristic).",
             G::ResetAccumulation),
        [](auto& s) -> auto& { return s.render.mis; });
    add(spec("render.adaptive", T::Bool, kAny, kAny, "",
             "Adaptive sampling: after a warm-up pass or two everywhere, each pass goes only to the pixel blocks "
             "whose estimated error (all samples' mean against half of them), over the root of their samples and "
             "rays per sample, is at least the image's mean, and they take its samples several times over, so that "
             "each sample goes where it lowers the image's MSE most for its time; render.spp is then the mean over "
             "the pixels. On by default with render.sampler sobol and independent; stratified and zsobol lay out "
             "render.spp samples per pixel, so with them it stays off, and asking for it is an error "
             "(bench/adaptive_sampling.md).",
             G::RecompileShader),
        [](auto& s) -> auto& { return s.render.adaptive; });
    add(spec("render.exposure", T::Float, atLeast(-20), atMost(20), "EV stops",
             "Display value = linear value x 2^exposure (PNG only).", G::Redisplay),
        [](auto& s) -> auto& { return s.render.exposure; });
    add(spec("render.tone_map", T::Enum, kAny, kAny, "",
             "Curve from linear radiance to display values (PNG only; EXR stays linear).", G::Redisplay,
             {{"clamp", static_cast<int>(ToneMap::Clamp)},
              {"reinhard", static_cast<int>(ToneMap::Reinhard)},
              {"aces", static_cast<int>(ToneMap::AcesFit)},
              {"none", static_cast<int>(ToneMap::Clamp), true}}),
        [](auto& s) -> auto& { return s.render.toneMap; });
    add(spec("render.show_mip_level", T::Int, atLeast(0), atMost(1), "",
             "1 = textured surfaces show the mip level chosen by ray cones (blue 0, green 4, red 8+).",
             G::RecompileShader),
        [](auto& s) -> auto& { return s.render.showMipLevel; });
    add(spec("render.stage", T::Enum, kAny, kAny, "",
             "Teaching: the renderer built up in stages: primary (flat albedo of the first hit), emission "
             "(+ emitters and sky seen directly), lambert (+ path tracing, all materials Lambertian), ggx "
             "(+ specular and glass), textures (+ image textures), full (+ depth of field).",
             G::RecompileShader,
             {{"primary", static_cast<int>(RenderStage::Primary)},
              {"emission", static_cast<int>(RenderStage::Emission)},
              {"lambert", static_cast<int>(RenderStage::Lambert)},
              {"ggx", static_cast<int>(RenderStage::Ggx)},
              {"textures", static_cast<int>(RenderStage::Textures)},
              {"full", static_cast<int>(RenderStage::Full)}}),
        [](auto& s) -> auto& { return s.render.stage; });
    add(spec("render.sampler", T::Enum, kAny, kAny, "",
             "How each path's random numbers are made: independent (hashed PCG), stratified (jittered "
             "strata, in a random order per pixel and dimension), sobol (Owen-scrambled Sobol, Burley "
             "2020) or zsobol (one Sobol sequence over the pixels in Morton order, so that the error is "
             "blue noise across the screen, Ahmed & Wonka 2020). Dimensions: pixel 0-1, lens 2-3, then 8 per bounce from 4 (sampler.glsl).",
             G::RecompileShader, samplerNames),
        [](auto& s) -> auto& { return s.render.sampler; });
    add(spec("render.diffuse_sampling", T::Enum, kAny, kAny, "",
             "Directions of the diffuse lobe: cosine (pdf cos/pi, a Lambert sample weighs exactly its albedo) or "
             "uniform over the hemisphere (pdf 1/(2 pi), the naive estimator; bench/estimator_stages.md).",
             G::RecompileShader,
             {{"cosine", static_cast<int>(DiffuseSampling::Cosine)},
              {"uniform", static_cast<int>(DiffuseSampling::Uniform)}}),
        [](auto& s) -> auto& { return s.render.diffuseSampling; });
    add(spec("render.ggx_sampling", T::Enum, kAny, kAny, "",
             "Microfacet normals of the GGX lobes (specular and rough glass): vndf (visible normals, Heitz 2018) "
             "or d_cos (D(h) cos(theta_h), Walter et al. 2007: weights blow up at grazing angles).",
             G::RecompileShader,
             {{"vndf", static_cast<int>(GgxSampling::Vndf)}, {"d_cos", static_cast<int>(GgxSampling::DCos)}}),
        [](auto& s) -> auto& { return s.render.ggxSampling; });
    add(spec("render.light_selection", T::Enum, kAny, kAny, "",
             "With nee: which light a light sample goes to: power (bounded lights by their power, the sky half "
             "beside them) or uniform (every light, the sky counted as one, an equal share).",
             G::RecompileShader,
             {{"power", static_cast<int>(LightSelection::Power)},
              {"uniform", static_cast<int>(LightSelection::Uniform)}}),
        [](auto& s) -> auto& { return s.render.lightSelection; });
    add(spec("render.light_sampling", T::Enum, kAny, kAny, "",
             "With nee: how a light sample finds a point on an emissive triangle: solid_angle (uniform over the "
             "solid angle it subtends, Arvo 1995; by area where that is below 1e-3 sr or nearly a hemisphere) or "
             "area (uniform over its area: the density per solid angle carries 1/r^2 and the light's cosine, noisy "
             "close to a large light; bench/estimator_stages.md).",
             G::RecompileShader,
             {{"solid_angle", static_cast<int>(LightSampling::SolidAngle)},
              {"area", static_cast<int>(LightSampling::Area)}}),
        [](auto& s) -> auto& { return s.render.lightSampling; });
    add(spec("render.accel", T::Enum, kAny, kAny, "",
             "How rays find surfaces: bvh (two-level bounding volume hierarchy; with at most 16 objects a "
             "loop over their boxes, and meshes of at most 16 triangles tested without their tree, which the "
             "heat views still count), boxes (a flat list of object boxes, each hit box's primitives all "
             "tested) or none (every primitive tested). Same image, different cost (heat views, "
             "bench/estimator_stages.md, bench/mesh_rays.md).",
             G::RecompileShader,
             {{"bvh", static_cast<int>(Accel::Bvh)},
              {"boxes", static_cast<int>(Accel::Boxes)},
              {"none", static_cast<int>(Accel::None)}}),
        [](auto& s) -> auto& { return s.render.accel; });

    // --- sky ---
    add(spec("sky.type", T::Enum, kAny, kAny, "",
             "Constant radiance, a blend from bottom (looking down) to top (looking up), or an HDR image (sky.map).",
             G::ReloadScene,
             {{"constant", static_cast<int>(Sky::Type::Constant)},
              {"gradient", static_cast<int>(Sky::Type::Gradient)},
              {"map", static_cast<int>(Sky::Type::Map)}}),
        [](auto& s) -> auto& { return s.sky.type; });
    add(spec("sky.color", T::Rgb, atLeast(0), kAny, "radiance",
             "Constant sky: its radiance (ignored by gradient).", G::ResetAccumulation),
        [](auto& s) -> auto& { return s.sky.color; });
    add(spec("sky.top", T::Rgb, atLeast(0), kAny, "radiance",
             "Gradient sky: radiance straight up (+y).", G::ResetAccumulation),
        [](auto& s) -> auto& { return s.sky.top; });
    add(spec("sky.bottom", T::Rgb, atLeast(0), kAny, "radiance",
             "Gradient sky: radiance straight down (-y).", G::ResetAccumulation),
        [](auto& s) -> auto& { return s.sky.bottom; });
    add(spec("sky.rotation", T::Float, atLeast(-360), atMost(360), "degrees",
             "Map sky: turns the image about the up (+y) axis.", G::ResetAccumulation),
        [](auto& s) -> auto& { return s.sky.rotation; });
    add(spec("sky.strength", T::Float, atLeast(0), kAny, "factor", "Multiplies the sky radiance.",
             G::ResetAccumulation),
        [](auto& s) -> auto& { return s.sky.strength; });

    // --- ao ---
    add(spec("ao.distance", T::Float, above(0), kAny, "world units",
             "Ambient-occlusion view: a ray from the first hit that travels this far without hitting anything is open.",
             G::ResetAccumulation),
        [](auto& s) -> auto& { return s.ao.distance; });
    add(spec("ao.rays", T::Int, atLeast(1), atMost(64), "rays",
             "Ambient-occlusion view: cosine-weighted rays per camera sample, drawn by render.sampler (independent: k rays give 1/k of one ray's variance; the others stratify them).",
             G::ResetAccumulation),
        [](auto& s) -> auto& { return s.ao.rays; });
    return t;
}

std::vector<MaterialParamSpec> buildMaterialTable() {
    using T = ParamType;
    std::vector<MaterialParamSpec> t;
    auto add = [&t](ValueSpec v, auto ref) { t.push_back(makeField<Material>(std::move(v), ref)); };
    add(spec("albedo", T::Rgb, atLeast(0), atMost(1), "reflectance",
             "Lambertian (diffuse) reflectance per channel.", Trigger::UpdateMaterials),
        [](auto& m) -> auto& { return m.albedo; });
    add(spec("roughness", T::Float, atLeast(0), atMost(1), "",
             "Perceptual roughness r of the specular lobe; GGX alpha = r^2 (below 0.0316: a mirror).",
             Trigger::UpdateMaterials),
        [](auto& m) -> auto& { return m.roughness; });
    add(spec("f0", T::Rgb, atLeast(0), atMost(1), "reflectance",
             "Specular reflectance at normal incidence (0.04 plastic, coloured for metals; 0 = no specular).",
             Trigger::UpdateMaterials),
        [](auto& m) -> auto& { return m.f0; });
    add(spec("transmission", T::Float, atLeast(0), atMost(1), "fraction",
             "Fraction of the surface that is glass of index ior, smooth or rough by its roughness (the rest is albedo / f0).",
             Trigger::UpdateMaterials),
        [](auto& m) -> auto& { return m.transmission; });
    add(spec("ior", T::Float, above(0), kAny, "",
             "Index of refraction of the inside relative to the outside (glass 1.5).", Trigger::UpdateMaterials),
        [](auto& m) -> auto& { return m.ior; });
    add(spec("emission", T::Rgb, atLeast(0), kAny, "radiance",
             "Emitted colour; emitted radiance = emission x strength.", Trigger::UpdateMaterials),
        [](auto& m) -> auto& { return m.emission; });
    add(spec("strength", T::Float, atLeast(0), kAny, "factor", "Multiplies emission (0 = not a light).",
             Trigger::UpdateMaterials),
        [](auto& m) -> auto& { return m.emissionStrength; });
    add(spec("metallic", T::Float, atLeast(0), atMost(1), "fraction",
             "Metallic workflow: f0 = mix(f0, base colour, m), albedo = base colour x (1 - m); base = albedo x albedo_texture.",
             Trigger::UpdateMaterials),
        [](auto& m) -> auto& { return m.metallic; });
    add(spec("normal_scale", T::Float, atLeast(0), kAny, "factor",
             "Scales the normal map's x and y (0 = flat, 1 = as stored).", Trigger::UpdateMaterials),
        [](auto& m) -> auto& { return m.normalScale; });
    add(spec("occlusion_strength", T::Float, atLeast(0), atMost(1), "factor",
             "With occlusion_texture: occlusion = 1 + strength x (texel - 1), as glTF's occlusionTexture.strength.",
             Trigger::UpdateMaterials),
        [](auto& m) -> auto& { return m.occlusionStrength; });
    return t;
}

std::vector<SphereParamSpec> buildSphereTable() {
    using T = ParamType;
    std::vector<SphereParamSpec> t;
    auto add = [&t](ValueSpec v, auto ref) { t.push_back(makeField<Sphere>(std::move(v), ref)); };
    add(spec("center", T::Vec3, kAny, kAny, "world units", "Centre of the sphere.", Trigger::MoveObjects),
        [](auto& s) -> auto& { return s.center; });
    add(spec("radius", T::Float, above(0), kAny, "world units", "Radius of the sphere.", Trigger::MoveObjects),
        [](auto& s) -> auto& { return s.radius; });
    return t;
}

std::string lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

bool violatesMin(const Bound& b, double v) { return b.inclusive ? v < b.value : v <= b.value; }
bool violatesMax(const Bound& b, double v) { return b.inclusive ? v > b.value : v >= b.value; }

std::string rangeText(const std::optional<Bound>& lo, const std::optional<Bound>& hi) {
    if (lo && hi) {
        return std::string(lo->inclusive ? "[" : "(") + formatNumber(lo->value) + ", " +
               formatNumber(hi->value) + (hi->inclusive ? "]" : ")");
    }
    if (lo) return std::string(lo->inclusive ? ">= " : "> ") + formatNumber(lo->value);
    if (hi) return std::string(hi->inclusive ? "<= " : "< ") + formatNumber(hi->value);
    return "any";
}

} // namespace

std::string_view ValueSpec::section() const {
    auto dot = key.find('.');
    return dot == std::string_view::npos ? std::string_view{} : key.substr(0, dot);
}

std::string_view ValueSpec::name() const {
    auto dot = key.find('.');
    return dot == std::string_view::npos ? key : key.substr(dot + 1);
}

const EnumName* ValueSpec::findEnum(std::string_view n) const {
    for (const EnumName& e : enumNames)
        if (e.name == n) return &e;
    return nullptr;
}

std::string_view ValueSpec::enumName(std::int64_t value) const {
    for (const EnumName& e : enumNames)
        if (!e.alias && e.value == value) return e.name;
    return {};
}

const std::vector<ParamSpec>& sceneParameters() {
    static const std::vector<ParamSpec> table = buildSceneTable();
    return table;
}

const ParamSpec* findParameter(std::string_view dottedKey) {
    for (const ParamSpec& p : sceneParameters())
        if (p.key == dottedKey) return &p;
    return nullptr;
}

const std::vector<MaterialParamSpec>& materialParameters() {
    static const std::vector<MaterialParamSpec> table = buildMaterialTable();
    return table;
}

static std::vector<TransformParamSpec> buildTransformTable() {
    using T = ParamType;
    std::vector<TransformParamSpec> t;
    auto add = [&t](ValueSpec v, auto ref) { t.push_back(makeField<Transform>(std::move(v), ref)); };
    add(spec("transform.translation", T::Vec3, kAny, kAny, "world units",
             "Moves the object (applied last).", Trigger::MoveObjects),
        [](auto& x) -> auto& { return x.translation; });
    add(spec("transform.rotation", T::Vec3, kAny, kAny, "degrees",
             "Rotation about x, then y, then z (world axes), after scaling.", Trigger::MoveObjects),
        [](auto& x) -> auto& { return x.rotation; });
    add(spec("transform.scale", T::Vec3, above(0), kAny, "factor",
             "Scale per axis, or one number for all three (applied first); spheres need all three equal.",
             Trigger::MoveObjects),
        [](auto& x) -> auto& { return x.scale; });
    return t;
}

const std::vector<TransformParamSpec>& transformParameters() {
    static const std::vector<TransformParamSpec> table = buildTransformTable();
    return table;
}

static std::vector<LightParamSpec> buildLightTable() {
    using T = ParamType;
    using L = Light::Type;
    std::vector<LightParamSpec> t;
    auto add = [&t](ValueSpec v, auto ref) { t.push_back(makeField<Light>(std::move(v), ref)); };
    add(spec("lights[].type", T::Enum, kAny, kAny, "",
             "point (intensity from a position), spot (a point limited to a cone) or distant (parallel light, the sun).",
             Trigger::ReloadScene, {{"point", int(L::Point)}, {"spot", int(L::Spot)}, {"distant", int(L::Distant)}}),
        [](auto& l) -> auto& { return l.type; });
    add(spec("lights[].position", T::Vec3, kAny, kAny, "world units", "Point, spot: where the light is.",
             Trigger::UpdateMaterials),
        [](auto& l) -> auto& { return l.position; });
    add(spec("lights[].direction", T::Vec3, kAny, kAny, "direction",
             "Spot: the cone's axis; distant: the direction the light travels (any length > 0).",
             Trigger::UpdateMaterials),
        [](auto& l) -> auto& { return l.direction; });
    add(spec("lights[].intensity", T::Rgb, atLeast(0), kAny, "W/sr",
             "Point, spot: radiant intensity (a colour or one number); not with power.", Trigger::UpdateMaterials),
        [](auto& l) -> auto& { return l.intensity; });
    add(spec("lights[].power", T::Float, atLeast(0), kAny, "W",
             "Point, spot: total emitted power instead of intensity (grey; point I = P / 4pi, spot I = P / (2pi (1 - (cos inner + cos outer) / 2))).",
             Trigger::UpdateMaterials),
        [](auto& l) -> auto& { return l.power; });
    add(spec("lights[].inner_angle", T::Float, atLeast(0), atMost(90), "degrees",
             "Spot: full intensity within this angle of the axis; smoothstep of cos down to outer_angle.",
             Trigger::UpdateMaterials),
        [](auto& l) -> auto& { return l.innerAngle; });
    add(spec("lights[].outer_angle", T::Float, atLeast(0), atMost(90), "degrees",
             "Spot: no light beyond this angle from the axis; >= inner_angle.", Trigger::UpdateMaterials),
        [](auto& l) -> auto& { return l.outerAngle; });
    add(spec("lights[].irradiance", T::Rgb, atLeast(0), kAny, "W/m^2",
             "Distant: irradiance E on a surface facing the light.", Trigger::UpdateMaterials),
        [](auto& l) -> auto& { return l.irradiance; });
    add(spec("lights[].angular_radius", T::Float, atLeast(0), below(90), "degrees",
             "Distant: half-angle of the light's disc (the sun: 0.27); 0 = a delta light no ray can hit.",
             Trigger::UpdateMaterials),
        [](auto& l) -> auto& { return l.angularRadius; });
    return t;
}

const std::vector<LightParamSpec>& lightParameters() {
    static const std::vector<LightParamSpec> table = buildLightTable();
    return table;
}

std::vector<std::string_view> lightKeysOf(Light::Type type) {
    switch (type) {
    case Light::Type::Point: return {"position", "intensity", "power"};
    case Light::Type::Spot: return {"position", "direction", "intensity", "power", "inner_angle", "outer_angle"};
    case Light::Type::Distant: return {"direction", "irradiance", "angular_radius"};
    }
    return {};
}

const std::vector<DisplacementParamSpec>& displacementParameters() {
    static const std::vector<DisplacementParamSpec> table = [] {
        std::vector<DisplacementParamSpec> t;
        auto add = [&t](ValueSpec v, auto ref) { t.push_back(makeField<MeshDisplacement>(std::move(v), ref)); };
        add(spec("displacement_scale", ParamType::Float, kAny, kAny, "object units",
                 "With displacement_texture: a vertex moves along its normal by this x the texture's value (negative: inwards).",
                 Trigger::ReloadScene),
            [](auto& d) -> auto& { return d.scale; });
        add(spec("displacement_subdivision", ParamType::Int, atLeast(0), atMost(8), "levels",
                 "With displacement_texture: each triangle is split into 4^n before displacing.", Trigger::ReloadScene),
            [](auto& d) -> auto& { return d.subdivision; });
        return t;
    }();
    return table;
}

const std::vector<std::string_view>& meshKeys() {
    static const std::vector<std::string_view> keys = {"file", "positions", "indices", "normals", "uvs", "emission_sides",
                                                       "displacement_texture"};
    return keys;
}

const std::vector<TextureSlot>& textureSlots() {
    static const std::vector<TextureSlot> slots = {
        {"albedo_texture", &Material::albedoTexture, &Material::albedoTextureIndex, false},
        {"normal_texture", &Material::normalTexture, &Material::normalTextureIndex, true},
        {"roughness_texture", &Material::roughnessTexture, &Material::roughnessTextureIndex, true},
        {"metallic_texture", &Material::metallicTexture, &Material::metallicTextureIndex, true},
        {"emission_texture", &Material::emissionTexture, &Material::emissionTextureIndex, false},
        {"specular_texture", &Material::specularTexture, &Material::specularTextureIndex, false},
        {"occlusion_texture", &Material::occlusionTexture, &Material::occlusionTextureIndex, true},
    };
    return slots;
}

const std::vector<std::string_view>& materialFileKeys() {
    static const std::vector<std::string_view> keys = [] {
        std::vector<std::string_view> k;
        for (const TextureSlot& s : textureSlots()) k.push_back(s.key);
        return k;
    }();
    return keys;
}

const std::vector<PathKey>& pathKeys() {
    static const std::vector<PathKey> keys = [] {
        std::vector<PathKey> k = {{PathScope::Scene, "sky.map"}, {PathScope::Object, "file"},
                                  {PathScope::Object, "displacement_texture"}};
        for (const TextureSlot& s : textureSlots()) k.push_back({PathScope::Material, s.key});
        return k;
    }();
    return keys;
}

const std::vector<SphereParamSpec>& sphereParameters() {
    static const std::vector<SphereParamSpec> table = buildSphereTable();
    return table;
}

std::optional<std::string> checkScalar(const ValueSpec& spec, double v) {
    if (!std::isfinite(v)) return "must be finite, got " + formatNumber(v);
    const bool integral = spec.type == ParamType::Int || spec.type == ParamType::UInt ||
                          spec.type == ParamType::Enum || spec.type == ParamType::Bool;
    if (integral && v != std::floor(v)) return "must be an integer, got " + formatNumber(v);
    const bool low = spec.min && violatesMin(*spec.min, v);
    const bool high = spec.max && violatesMax(*spec.max, v);
    if (low || high) {
        if (spec.min && spec.max) return "must be in " + rangeText(spec.min, spec.max) + ", got " + formatNumber(v);
        return "must be " + rangeText(spec.min, spec.max) + ", got " + formatNumber(v);
    }
    // Limits of the storage type, for parameters whose table range leaves them open.
    switch (spec.type) {
    case ParamType::Int:
    case ParamType::Enum:
        if (v < kIntMin) return "must be >= " + formatNumber(kIntMin) + ", got " + formatNumber(v);
        if (v > kIntMax) return "must be <= " + formatNumber(kIntMax) + ", got " + formatNumber(v);
        break;
    case ParamType::Bool:
        if (v != 0 && v != 1) return "must be true or false, got " + formatNumber(v);
        break;
    case ParamType::UInt:
        if (v < 0 || v > kUIntMax) return "must be in [0, " + formatNumber(kUIntMax) + "], got " + formatNumber(v);
        break;
    default: {
        if (std::fabs(v) > kFloatMax)
            return "is too large for a 32-bit float (magnitude must be <= " + formatNumber(kFloatMax) +
                   "), got " + formatNumber(v);
        // The GPU sees single precision: 1e-50 passes "> 0" as a double but is 0 as a float.
        const double f = static_cast<float>(v);
        if ((spec.min && violatesMin(*spec.min, f)) || (spec.max && violatesMax(*spec.max, f)))
            return "must be " + std::string(spec.min && spec.max ? "in " : "") + rangeText(spec.min, spec.max) +
                   ", got " + formatNumber(v) + " (" + formatNumber(f) + " as a 32-bit float)";
        break;
    }
    }
    return std::nullopt;
}

std::optional<std::string> checkValue(const ValueSpec& spec, const ParamValue& value) {
    switch (spec.type) {
    case ParamType::Vec3:
    case ParamType::Rgb: {
        const auto* v = std::get_if<glm::vec3>(&value);
        if (!v) return std::string("expected a vector value");
        for (int i = 0; i < 3; ++i)
            if (auto err = checkScalar(spec, static_cast<double>((*v)[i])))
                return "component " + std::to_string(i) + " " + *err;
        return std::nullopt;
    }
    case ParamType::Float: {
        const auto* v = std::get_if<double>(&value);
        if (!v) return std::string("expected a real number");
        return checkScalar(spec, *v);
    }
    case ParamType::Enum: {
        const auto* v = std::get_if<std::int64_t>(&value);
        if (!v) return std::string("expected an enum value");
        if (spec.enumName(*v).empty()) return "is not a valid value: " + std::to_string(*v);
        return std::nullopt;
    }
    case ParamType::Int:
    case ParamType::UInt:
    case ParamType::Bool: {
        const auto* v = std::get_if<std::int64_t>(&value);
        if (!v) return std::string("expected an integer");
        return checkScalar(spec, static_cast<double>(*v));
    }
    }
    return std::nullopt;
}

std::string formatNumber(double value) {
    char buf[64];
    std::to_chars_result r{};
    if (std::isfinite(value) && value == std::floor(value) && std::fabs(value) < 1e15) {
        r = std::to_chars(buf, buf + sizeof buf, value, std::chars_format::fixed, 0);  // 3000000000, not 3e+09
        return std::string(buf, r.ptr);
    }
    const float f = static_cast<float>(value);
    // Values that came from float fields print in float's shortest form (0.8, not 0.800000011920929).
    if (std::isfinite(value) && std::fabs(value) <= kFloatMax && static_cast<double>(f) == value)
        r = std::to_chars(buf, buf + sizeof buf, f);
    else
        r = std::to_chars(buf, buf + sizeof buf, value);
    return std::string(buf, r.ptr);
}

std::string formatValue(const ValueSpec& spec, const ParamValue& value) {
    if (const auto* v = std::get_if<glm::vec3>(&value)) {
        return "[" + formatNumber(static_cast<double>(v->x)) + ", " + formatNumber(static_cast<double>(v->y)) +
               ", " + formatNumber(static_cast<double>(v->z)) + "]";
    }
    if (const auto* d = std::get_if<double>(&value)) return formatNumber(*d);
    const std::int64_t i = std::get<std::int64_t>(value);
    if (spec.type == ParamType::Enum) return std::string(spec.enumName(i));
    if (spec.type == ParamType::Bool) return i != 0 ? "true" : "false";
    return std::to_string(i);
}

std::string describeRange(const ValueSpec& spec) {
    if (spec.type == ParamType::Enum) {
        std::string out;
        for (const EnumName& e : spec.enumNames) {
            if (e.alias) continue;
            if (!out.empty()) out += ", ";
            out += e.name;
            for (const EnumName& a : spec.enumNames)
                if (a.alias && a.value == e.value) out += " (or " + std::string(a.name) + ")";
        }
        return out;
    }
    if (spec.type == ParamType::Bool) return "true, false";
    return rangeText(spec.min, spec.max);
}

std::string_view typeName(ParamType type) {
    switch (type) {
    case ParamType::Int: return "int";
    case ParamType::UInt: return "uint";
    case ParamType::Float: return "float";
    case ParamType::Vec3: return "vec3";
    case ParamType::Rgb: return "rgb";
    case ParamType::Enum: return "enum";
    case ParamType::Bool: return "bool";
    }
    return "?";
}

std::string_view triggerName(Trigger trigger) {
    switch (trigger) {
    case Trigger::Redisplay: return "redisplay";
    case Trigger::ResetAccumulation: return "reset accumulation";
    case Trigger::MoveObjects: return "move objects";
    case Trigger::UpdateMaterials: return "update materials";
    case Trigger::RecompileShader: return "recompile shader";
    case Trigger::ReloadScene: return "reload scene";
    }
    return "?";
}

// Wagner-Fischer dynamic programme for the Levenshtein distance, keeping one row
// (R. A. Wagner, M. J. Fischer, "The String-to-String Correction Problem", JACM 21(1), 1974).
std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];  // D[i-1][j-1]
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t up = row[j];  // D[i-1][j]
            const std::size_t substitute = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
            row[j] = std::min({up + 1, row[j - 1] + 1, substitute});
            diagonal = up;
        }
    }
    return row[b.size()];
}

std::string_view closestMatch(std::string_view word, const std::vector<std::string_view>& candidates) {
    const std::string w = lower(word);
    std::string_view best;
    std::size_t bestDistance = std::numeric_limits<std::size_t>::max();
    for (std::string_view c : candidates) {
        const std::size_t d = editDistance(w, lower(c));
        if (d < bestDistance) {
            bestDistance = d;
            best = c;
        }
    }
    // Plausible typo: a few edits, and fewer edits than the word has letters.
    const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
    if (best.empty() || bestDistance > limit || bestDistance >= std::max(word.size(), best.size())) return {};
    return best;
}

} // namespace raylab
