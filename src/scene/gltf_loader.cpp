#include "scene/gltf_loader.h"

#include "texture/image_size.h"

#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <new>
#include <optional>

namespace raylab {
namespace {

std::string at(const char* array, std::size_t index) { return std::string(array) + "[" + std::to_string(index) + "]"; }

// "7 is not a node (3 in the file)" unless 0 <= index < size.
std::optional<std::string> badIndex(long long index, std::size_t size, const char* what) {
    if (index >= 0 && std::size_t(index) < size) return std::nullopt;
    return std::to_string(index) + " is not " + what + " (" + std::to_string(size) + " in the file)";
}

// An accessor whose every element was checked to lie inside its buffer view and buffer.
struct AccessorView {
    std::string path;                     // "accessors[k]", for messages
    const unsigned char* data = nullptr;  // element 0
    std::size_t stride = 0;
    std::size_t count = 0;
    int components = 0;
    int componentType = 0;
    bool normalized = false;

    // Component k of element i (normalised integers are scaled to [0, 1]).
    double get(std::size_t i, int k) const {
        const unsigned char* p = data + i * stride + std::size_t(k) * std::size_t(componentSize());
        switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p, 4); return f; }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? *p / 255.0 : double(*p);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { std::uint16_t s; std::memcpy(&s, p, 2); return normalized ? s / 65535.0 : double(s); }
        default: { std::uint32_t u; std::memcpy(&u, p, 4); return u; }
        }
    }
    int componentSize() const { return tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(componentType)); }
};

struct Reader {
    const tinygltf::Model& model;
    const std::string& name;
    Mesh& mesh;
    bool anyMaterial = false;        // some primitive names a material
    std::vector<bool> onPath;        // nodes visited from the current root (glTF nodes form a tree)

    [[noreturn]] void fail(const std::string& what) const { throw GltfError(name + ": " + what); }

    // The accessor `where` names (e.g. meshes[0].primitives[1].attributes.NORMAL), checked for the
    // number of components `components` (1 scalar, 2 VEC2, 3 VEC3) and that every byte it reads lies
    // inside its buffer view and buffer, without overflow.
    AccessorView view(int index, const std::string& where, int components, bool integersOnly) const {
        if (auto bad = badIndex(index, model.accessors.size(), "an accessor")) fail(where + ": " + *bad);
        const tinygltf::Accessor& a = model.accessors[std::size_t(index)];
        AccessorView out;
        out.path = at("accessors", std::size_t(index));
        const std::string& ap = out.path;
        if (a.sparse.isSparse) fail(ap + ".sparse: sparse accessors are not supported");
        switch (a.componentType) {
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: break;
        case TINYGLTF_COMPONENT_TYPE_FLOAT:
            if (integersOnly) fail(ap + ".componentType: " + where + " needs unsigned integers, got 5126 (float)");
            break;
        default: fail(ap + ".componentType: unsupported component type " + std::to_string(a.componentType));
        }
        const int n = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
        if (n != components)
            fail(ap + ".type: " + where + " needs " + std::to_string(components) + " component" +
                 (components == 1 ? "" : "s") + " per element, got " + std::to_string(n));
        out.components = n;
        out.componentType = a.componentType;
        out.normalized = a.normalized;
        out.count = a.count;
        if (a.bufferView < 0) fail(ap + ".bufferView: the accessor has no data");
        if (auto bad = badIndex(a.bufferView, model.bufferViews.size(), "a bufferView")) fail(ap + ".bufferView: " + *bad);
        const tinygltf::BufferView& v = model.bufferViews[std::size_t(a.bufferView)];
        const std::string vp = at("bufferViews", std::size_t(a.bufferView));
        if (auto bad = badIndex(v.buffer, model.buffers.size(), "a buffer")) fail(vp + ".buffer: " + *bad);
        const tinygltf::Buffer& b = model.buffers[std::size_t(v.buffer)];
        if (v.byteOffset > b.data.size() || v.byteLength > b.data.size() - v.byteOffset)
            fail(vp + ": byteOffset " + std::to_string(v.byteOffset) + " + byteLength " + std::to_string(v.byteLength) +
                 " is past the end of " + at("buffers", std::size_t(v.buffer)) + " (" + std::to_string(b.data.size()) +
                 " bytes)");
        const std::size_t element = std::size_t(n) * std::size_t(out.componentSize());
        out.stride = v.byteStride == 0 ? element : v.byteStride;
        if (out.stride < element)
            fail(vp + ".byteStride: " + std::to_string(v.byteStride) + " is smaller than an element of " + ap + " (" +
                 std::to_string(element) + " bytes)");
        if (out.count == 0) return out;
        // byteOffset + (count - 1) * stride + element <= byteLength, evaluated without wrapping.
        const bool fits = a.byteOffset <= v.byteLength && element <= v.byteLength - a.byteOffset &&
                          out.count - 1 <= (v.byteLength - a.byteOffset - element) / out.stride;
        if (!fits)
            fail(ap + ": byteOffset " + std::to_string(a.byteOffset) + " + count " + std::to_string(a.count) +
                 " x stride " + std::to_string(out.stride) + " is past the end of " + vp + " (byteLength " +
                 std::to_string(v.byteLength) + ")");
        out.data = b.data.data() + v.byteOffset + a.byteOffset;
        return out;
    }

    static glm::mat4 localMatrix(const tinygltf::Node& n) {
        if (n.matrix.size() == 16) {
            glm::mat4 m(1.0f);
            for (int c = 0; c < 4; ++c)
                for (int r = 0; r < 4; ++r) m[c][r] = float(n.matrix[std::size_t(4 * c + r)]);   // column-major
            return m;
        }
        glm::mat4 m(1.0f);
        if (n.translation.size() == 3)
            m = glm::translate(m, glm::vec3(float(n.translation[0]), float(n.translation[1]), float(n.translation[2])));
        if (n.rotation.size() == 4)   // glTF quaternions are x, y, z, w
            m *= glm::mat4_cast(glm::quat(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]),
                                          float(n.rotation[2])));
        if (n.scale.size() == 3) m = glm::scale(m, glm::vec3(float(n.scale[0]), float(n.scale[1]), float(n.scale[2])));
        return m;
    }

    void finite(const std::vector<double>& values, const std::string& where) const {
        for (std::size_t i = 0; i < values.size(); ++i)
            if (!std::isfinite(values[i]) || std::abs(values[i]) > double(std::numeric_limits<float>::max()))
                fail(where + "[" + std::to_string(i) + "]: not a finite 32-bit float");
    }

    void node(int index, const glm::mat4& parent, int depth, const std::string& where) {
        if (auto bad = badIndex(index, model.nodes.size(), "a node")) fail(where + ": " + *bad);
        const std::string np = at("nodes", std::size_t(index));
        if (depth > 64) fail(np + ": the node hierarchy is deeper than 64 (a cycle?)");
        if (onPath[std::size_t(index)]) fail(np + ": the node is reached twice (glTF nodes form a tree)");
        onPath[std::size_t(index)] = true;
        const tinygltf::Node& n = model.nodes[std::size_t(index)];
        finite(n.matrix, np + ".matrix");
        finite(n.translation, np + ".translation");
        finite(n.rotation, np + ".rotation");
        finite(n.scale, np + ".scale");
        const glm::mat4 world = parent * localMatrix(n);
        if (n.mesh >= 0) {
            if (auto bad = badIndex(n.mesh, model.meshes.size(), "a mesh")) fail(np + ".mesh: " + *bad);
            const auto& primitives = model.meshes[std::size_t(n.mesh)].primitives;
            for (std::size_t k = 0; k < primitives.size(); ++k)
                primitive(primitives[k], world, at("meshes", std::size_t(n.mesh)) + "." + at("primitives", k));
        }
        for (std::size_t c = 0; c < n.children.size(); ++c) node(n.children[c], world, depth + 1, np + "." + at("children", c));
    }

    // A tree of nodes (a scene's, or one node's when the file has no scene).
    void tree(const std::vector<int>& roots, const std::string& where) {
        onPath.assign(model.nodes.size(), false);
        for (std::size_t i = 0; i < roots.size(); ++i) node(roots[i], glm::mat4(1.0f), 0, where + "[" + std::to_string(i) + "]");
    }

    void primitive(const tinygltf::Primitive& p, const glm::mat4& world, const std::string& pp) {
        if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1) return;   // points and lines: skipped
        const auto pos = p.attributes.find("POSITION");
        if (pos == p.attributes.end()) fail(pp + ".attributes: a primitive has no POSITION");
        const auto nrm = p.attributes.find("NORMAL");
        const auto uv = p.attributes.find("TEXCOORD_0");
        const AccessorView positions = view(pos->second, pp + ".attributes.POSITION", 3, false);
        const std::size_t n = positions.count;
        std::optional<AccessorView> normals, uvs;
        if (nrm != p.attributes.end()) normals = view(nrm->second, pp + ".attributes.NORMAL", 3, false);
        if (uv != p.attributes.end()) uvs = view(uv->second, pp + ".attributes.TEXCOORD_0", 2, false);
        for (const std::optional<AccessorView>& a : {normals, uvs})
            if (a && a->count < n)
                fail(a->path + ".count: " + std::to_string(a->count) + " elements, fewer than the " + std::to_string(n) +
                     " positions of " + positions.path);
        if (n > std::numeric_limits<unsigned>::max() - mesh.positions.size())
            fail(positions.path + ".count: too many vertices");
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
        const unsigned base = unsigned(mesh.positions.size());
        auto element = [this](const AccessorView& a, std::size_t i) {
            glm::vec3 v(0.0f);
            for (int k = 0; k < a.components; ++k) {
                const double x = a.get(i, k);
                if (!std::isfinite(x) || std::abs(x) > double(std::numeric_limits<float>::max()))
                    fail(a.path + "[" + std::to_string(i) + "]: not a finite 32-bit float");
                v[k] = float(x);
            }
            return v;
        };
        for (std::size_t i = 0; i < n; ++i) {
            const glm::vec3 v = element(positions, i);
            mesh.positions.push_back(glm::vec3(world * glm::vec4(v, 1.0f)));
            if (normals) mesh.normals.push_back(glm::normalize(normalMatrix * element(*normals, i)));
            if (uvs) {
                const glm::vec3 t = element(*uvs, i);
                mesh.uvs.emplace_back(t.x, 1.0f - t.y);   // glTF's v runs downwards
            }
        }
        const std::size_t firstTriangle = mesh.triangles.size();
        if (p.indices >= 0) {
            const AccessorView indices = view(p.indices, pp + ".indices", 1, true);
            for (std::size_t i = 0; i + 2 < indices.count; i += 3) {
                glm::uvec3 t;
                for (int k = 0; k < 3; ++k) {
                    const double index = indices.get(i + std::size_t(k), 0);
                    if (index >= double(n))
                        fail(indices.path + "[" + std::to_string(i + std::size_t(k)) + "]: index " +
                             std::to_string(std::uint64_t(index)) + " is out of range (" + std::to_string(n) + " vertices)");
                    t[k] = base + unsigned(index);
                }
                mesh.triangles.push_back(t);
            }
        } else {
            for (unsigned i = 0; i + 2 < n; i += 3) mesh.triangles.emplace_back(base + i, base + i + 1, base + i + 2);
        }
        if (p.material >= 0)
            if (auto bad = badIndex(p.material, model.materials.size(), "a material")) fail(pp + ".material: " + *bad);
        anyMaterial |= p.material >= 0;
        mesh.triangleMaterials.resize(firstTriangle, -1);
        mesh.triangleMaterials.resize(mesh.triangles.size(), p.material);
    }
};

// The texel of level 0 nearest to uv in [0, 1]^2.
glm::vec4 nearestTexel(const Texture& t, glm::vec2 uv) {
    const MipLevel& l = t.levels.at(0);
    const int x = std::clamp(int(uv.x * float(l.width)), 0, l.width - 1);
    const int y = std::clamp(int(uv.y * float(l.height)), 0, l.height - 1);
    return l.texels[std::size_t(y) * std::size_t(l.width) + std::size_t(x)];
}

// KHR_materials_specular's f0 per texel: min(dielectric x colour.rgb, 1) x factor x strength.a, at
// the size of the larger of the two textures (the other read at the nearest texel), with its wraps.
Texture bakedSpecular(const Texture* colour, const Texture* strength, glm::vec3 dielectric, float factor) {
    const Texture* grid = colour;
    if (!grid || (strength && strength->levels[0].texels.size() > grid->levels[0].texels.size())) grid = strength;
    MipLevel base;
    base.width = grid->levels[0].width;
    base.height = grid->levels[0].height;
    base.texels.resize(grid->levels[0].texels.size());
    for (int y = 0; y < base.height; ++y)
        for (int x = 0; x < base.width; ++x) {
            const glm::vec2 uv((float(x) + 0.5f) / float(base.width), (float(y) + 0.5f) / float(base.height));
            const glm::vec3 c = colour ? glm::vec3(nearestTexel(*colour, uv)) : glm::vec3(1.0f);
            const float a = strength ? nearestTexel(*strength, uv).a : 1.0f;
            base.texels[std::size_t(y) * std::size_t(base.width) + std::size_t(x)] =
                glm::vec4(glm::min(dielectric * c, glm::vec3(1.0f)) * factor * a, 1.0f);
        }
    Texture t;
    t.levels = buildMipPyramid(std::move(base));
    t.wrapU = grid->wrapU;
    t.wrapV = grid->wrapV;
    return t;
}

TextureWrap wrapMode(int gl) {
    switch (gl) {
    case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE: return TextureWrap::ClampToEdge;
    case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT: return TextureWrap::MirroredRepeat;
    default: return TextureWrap::Repeat;
    }
}

// glTF materials → raylab materials (the table in scenes/FORMAT.md) and their images.
struct MaterialReader {
    const tinygltf::Model& model;
    const std::string& name;
    GltfAsset& asset;

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw GltfError(name + ": " + where + ": " + what);
    }

    // Texture `index` as a raylab texture (loaded once per texture and decoding); `where` is the
    // JSON path of the reference, for messages.
    int texture(int index, int texCoord, bool linearData, const std::string& where) {
        if (index < 0 || std::size_t(index) >= model.textures.size()) fail(where, "bad texture index " + std::to_string(index));
        if (texCoord != 0)
            asset.warnings.push_back(name + ": " + where + ": texCoord " + std::to_string(texCoord) +
                                     " is not supported; TEXCOORD_0 is used");
        const std::string key = (linearData ? "linear:" : "srgb:") + name + "#textures[" + std::to_string(index) + "]";
        for (std::size_t i = 0; i < asset.textures.size(); ++i)
            if (asset.textures[i].file == key) return int(i);
        Texture tex = decoded(index, linearData, where);
        tex.file = key;
        asset.textures.push_back(std::move(tex));
        return int(asset.textures.size() - 1);
    }

    // Texture `index` decoded, with its sampler's wrap modes, not yet among the asset's textures.
    Texture decoded(int index, bool linearData, const std::string& where) const {
        const tinygltf::Texture& t = model.textures[std::size_t(index)];
        const std::string tp = "textures[" + std::to_string(index) + "]";
        if (t.source < 0 || std::size_t(t.source) >= model.images.size()) fail(where, tp + ": no image (source)");
        const tinygltf::Image& im = model.images[std::size_t(t.source)];
        const std::string ip = "images[" + std::to_string(t.source) + "]" +
                               (im.uri.empty() || im.uri.rfind("data:", 0) == 0 ? "" : " '" + im.uri + "'");
        if (im.image.empty() || im.width <= 0 || im.height <= 0)
            fail(where, ip + ": cannot read" + (im.uri.empty() || im.uri.rfind("data:", 0) == 0 ? "" : ": no such file"));
        if (std::size_t(im.width) * std::size_t(im.height) * std::size_t(im.component) * std::size_t(im.bits / 8) >
            im.image.size())
            fail(where, ip + ": image data is shorter than its size");
        Texture tex;
        try {
            tex = textureFromPixels(im.image.data(), im.width, im.height, im.component, im.bits, linearData);
        } catch (const TextureError& e) {
            fail(where, ip + ": " + e.what());
        }
        if (t.sampler >= 0) {
            if (std::size_t(t.sampler) >= model.samplers.size()) fail(where, tp + ": bad sampler index");
            const tinygltf::Sampler& s = model.samplers[std::size_t(t.sampler)];
            tex.wrapU = wrapMode(s.wrapS);
            tex.wrapV = wrapMode(s.wrapT);
        }
        return tex;
    }

    static float clamp01(double v) { return float(std::min(1.0, std::max(0.0, v))); }

    // A textureInfo inside an extension, which tinygltf leaves as a Value: {"index": k, "texCoord": n}.
    std::optional<Texture> extensionTexture(const tinygltf::Value& ext, const char* key, bool linearData,
                                            const std::string& where) {
        if (!ext.Has(key)) return std::nullopt;
        const tinygltf::Value& v = ext.Get(key);
        const std::string tp = where + "." + key;
        if (!v.IsObject() || !v.Has("index") || !v.Get("index").IsInt())
            fail(tp, "expected a texture reference {\"index\": k}");
        const int index = v.Get("index").GetNumberAsInt();
        if (auto bad = badIndex(index, model.textures.size(), "a texture")) fail(tp + ".index", *bad);
        if (v.Has("texCoord") && (!v.Get("texCoord").IsInt() || v.Get("texCoord").GetNumberAsInt() != 0))
            asset.warnings.push_back(name + ": " + tp + ".texCoord: only TEXCOORD_0 is supported; it is used");
        return decoded(index, linearData, tp);
    }

    // KHR_materials_specular (with KHR_materials_ior's ior, default 1.5): the dielectric f0 =
    // min(F0(ior) x specularColorFactor x specularColorTexture.rgb, 1) x specularFactor x
    // specularTexture.a, as one f0 or, with a texture, baked per texel into a specular_texture under f0 1.
    void specular(const tinygltf::Material& g, const std::string& mp, Material& m) {
        const auto iorExt = g.extensions.find("KHR_materials_ior");
        double ior = 1.5;
        if (iorExt != g.extensions.end() && iorExt->second.Has("ior")) {
            const tinygltf::Value& v = iorExt->second.Get("ior");
            if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()) || v.GetNumberAsDouble() < 1.0)
                fail(mp + ".extensions.KHR_materials_ior.ior", "must be a number >= 1");
            ior = v.GetNumberAsDouble();
        }
        const double r = (ior - 1.0) / (ior + 1.0);
        m.f0 = glm::vec3(float(r * r));
        const auto found = g.extensions.find("KHR_materials_specular");
        if (found == g.extensions.end()) return;
        const tinygltf::Value& ext = found->second;
        const std::string ep = mp + ".extensions.KHR_materials_specular";
        double factor = 1.0;
        if (ext.Has("specularFactor")) {
            const tinygltf::Value& v = ext.Get("specularFactor");
            if (!v.IsNumber() || !(v.GetNumberAsDouble() >= 0.0 && v.GetNumberAsDouble() <= 1.0))
                fail(ep + ".specularFactor", "must be a number in [0, 1]");
            factor = v.GetNumberAsDouble();
        }
        glm::vec3 colour(1.0f);
        if (ext.Has("specularColorFactor")) {
            const tinygltf::Value& v = ext.Get("specularColorFactor");
            const auto component = [&v](int k) { return v.Get(k).IsNumber() ? v.Get(k).GetNumberAsDouble() : -1.0; };
            if (!v.IsArray() || v.ArrayLen() != 3 || !(std::isfinite(component(0)) && component(0) >= 0.0) ||
                !(std::isfinite(component(1)) && component(1) >= 0.0) || !(std::isfinite(component(2)) && component(2) >= 0.0))
                fail(ep + ".specularColorFactor", "must be three numbers >= 0");
            colour = glm::vec3(float(component(0)), float(component(1)), float(component(2)));
        }
        const glm::vec3 dielectric = m.f0 * colour;
        const std::optional<Texture> colourTexture = extensionTexture(ext, "specularColorTexture", false, ep);
        const std::optional<Texture> strengthTexture = extensionTexture(ext, "specularTexture", true, ep);
        if (!colourTexture && !strengthTexture) {
            m.f0 = glm::min(dielectric, glm::vec3(1.0f)) * float(factor);
            return;
        }
        Texture baked = bakedSpecular(colourTexture ? &*colourTexture : nullptr,
                                      strengthTexture ? &*strengthTexture : nullptr, dielectric, float(factor));
        baked.file = "linear:" + name + "#" + ep;
        asset.textures.push_back(std::move(baked));
        m.f0 = glm::vec3(1.0f);
        m.specularTextureIndex = int(asset.textures.size() - 1);
    }

    Material material(std::size_t k) {
        const tinygltf::Material& g = model.materials[k];
        const std::string mp = "materials[" + std::to_string(k) + "]";
        Material m;
        m.name = mp + (g.name.empty() ? "" : " " + g.name);
        const tinygltf::PbrMetallicRoughness& pbr = g.pbrMetallicRoughness;
        const std::string pp = mp + ".pbrMetallicRoughness";
        if (pbr.baseColorFactor.size() >= 3)
            m.albedo = glm::vec3(clamp01(pbr.baseColorFactor[0]), clamp01(pbr.baseColorFactor[1]),
                                 clamp01(pbr.baseColorFactor[2]));
        // glTF's dielectrics reflect 4% at normal incidence (ior 1.5) unless an extension says
        // otherwise; metals take the base colour as f0.
        specular(g, mp, m);
        m.metallic = clamp01(pbr.metallicFactor);
        m.roughness = clamp01(pbr.roughnessFactor);
        if (pbr.baseColorTexture.index >= 0)
            m.albedoTextureIndex = texture(pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, false,
                                           pp + ".baseColorTexture");
        if (pbr.metallicRoughnessTexture.index >= 0) {
            // One image: roughness in green, metallic in blue (as raylab's two keys read them).
            const int t = texture(pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord, true,
                                  pp + ".metallicRoughnessTexture");
            m.roughnessTextureIndex = t;
            m.metallicTextureIndex = t;
        }
        if (g.normalTexture.index >= 0) {
            m.normalTextureIndex = texture(g.normalTexture.index, g.normalTexture.texCoord, true, mp + ".normalTexture");
            m.normalScale = float(std::max(0.0, g.normalTexture.scale));
        }
        if (g.emissiveFactor.size() >= 3)
            m.emission = glm::vec3(float(std::max(0.0, g.emissiveFactor[0])), float(std::max(0.0, g.emissiveFactor[1])),
                                   float(std::max(0.0, g.emissiveFactor[2])));
        float strength = 1.0f;
        const auto ext = g.extensions.find("KHR_materials_emissive_strength");
        if (ext != g.extensions.end() && ext->second.Has("emissiveStrength")) {
            const tinygltf::Value& v = ext->second.Get("emissiveStrength");
            if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble()) || v.GetNumberAsDouble() < 0.0)
                fail(mp + ".extensions.KHR_materials_emissive_strength.emissiveStrength", "must be a number >= 0");
            strength = float(v.GetNumberAsDouble());
        }
        const bool emits = std::max({m.emission.r, m.emission.g, m.emission.b}) > 0.0f && strength > 0.0f;
        m.emissionStrength = emits ? strength : 0.0f;
        if (emits && g.emissiveTexture.index >= 0)
            m.emissionTextureIndex = texture(g.emissiveTexture.index, g.emissiveTexture.texCoord, false,
                                             mp + ".emissiveTexture");
        m.doubleSided = g.doubleSided;
        if (g.alphaMode != "OPAQUE" && !g.alphaMode.empty())
            asset.warnings.push_back(name + ": " + mp + ".alphaMode: " + g.alphaMode +
                                     " is ignored; the material is opaque");
        if (g.occlusionTexture.index >= 0) {   // for the baked-ao debug view only: tracing finds occlusion itself
            m.occlusionTextureIndex = texture(g.occlusionTexture.index, g.occlusionTexture.texCoord, true,
                                              mp + ".occlusionTexture");
            m.occlusionStrength = clamp01(g.occlusionTexture.strength);
        }
        return m;
    }
};

// The files a glTF names (buffers, images), read for tinygltf: its own reader takes a directory's
// size as 2^63 - 1 and allocates that, so only regular files up to this size are read.
constexpr std::uintmax_t kMaxReferencedFileBytes = std::uintmax_t(1) << 31;

bool readReferencedFile(std::vector<unsigned char>* out, std::string* err, const std::string& path, void*) {
    auto refuse = [&](const std::string& what) {
        if (err) *err += path + ": " + what + "\n";
        return false;
    };
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) return refuse("cannot read: not a file");
    const std::uintmax_t size = std::filesystem::file_size(path, ec);
    if (ec) return refuse("cannot read: " + ec.message());
    if (size == 0) return refuse("cannot read: the file is empty");
    if (size > kMaxReferencedFileBytes)
        return refuse("cannot read: " + std::to_string(size) + " bytes, more than the limit of " +
                      std::to_string(kMaxReferencedFileBytes));
    std::ifstream in(path, std::ios::binary);
    out->resize(std::size_t(size));
    if (!in.read(reinterpret_cast<char*>(out->data()), std::streamsize(size))) return refuse("cannot read: read failed");
    return true;
}

// tinygltf's image decoding, after checking what it cannot: that an image's buffer view lies
// inside its buffer and that the header's size is within raylab's limits.
struct ImageLoad {
    const tinygltf::Model* model;   // filled by tinygltf before it reads images
};

bool loadImageChecked(tinygltf::Image* image, int index, std::string* err, std::string* warn, int width, int height,
                      const unsigned char* bytes, int size, void* user) {
    const tinygltf::Model& model = *static_cast<ImageLoad*>(user)->model;
    const std::string ip = at("images", std::size_t(index));
    auto refuse = [err](const std::string& what) {
        if (err) *err += what + "\n";
        return false;
    };
    if (image->bufferView >= 0) {   // tinygltf has checked both indices, not the byte range
        const tinygltf::BufferView& v = model.bufferViews[std::size_t(image->bufferView)];
        const tinygltf::Buffer& b = model.buffers[std::size_t(v.buffer)];
        if (v.byteOffset > b.data.size() || v.byteLength > b.data.size() - v.byteOffset)
            return refuse(ip + ".bufferView: " + at("bufferViews", std::size_t(image->bufferView)) + " (byteOffset " +
                          std::to_string(v.byteOffset) + ", byteLength " + std::to_string(v.byteLength) +
                          ") is past the end of " + at("buffers", std::size_t(v.buffer)) + " (" +
                          std::to_string(b.data.size()) + " bytes)");
    }
    if (size <= 0) return refuse(ip + ": the image is empty");
    if (const auto header = encodedImageSize(bytes, std::size_t(size)))
        if (const auto problem = imageSizeProblem(header->width, header->height)) return refuse(ip + ": " + *problem);
    // No user data: tinygltf's default decoding (rgba, 8 or 16 bits).
    return tinygltf::LoadImageData(image, index, err, warn, width, height, bytes, size, nullptr);
}

std::string withoutTrailingNewlines(std::string s) {
    while (!s.empty() && (s.back() == '\n' || s.back() == '\r')) s.pop_back();
    return s;
}

} // namespace

GltfAsset loadGltfAsset(const std::filesystem::path& file) {
    const std::string name = file.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(file, ec)) throw GltfError(name + ": cannot read: no such file");
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks({&tinygltf::FileExists, &tinygltf::ExpandFilePath, &readReferencedFile,
                           &tinygltf::WriteWholeFile, nullptr});
    ImageLoad images{&model};
    loader.SetImageLoader(&loadImageChecked, &images);
    std::string err, warn;
    const bool binary = file.extension() == ".glb" || file.extension() == ".GLB";
    if (!binary) {   // tinygltf accepts a NUL byte, and anything after it, behind the JSON document
        std::ifstream in(file, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (const std::size_t nul = text.find('\0'); nul != std::string::npos)
            throw GltfError(name + ": byte " + std::to_string(nul) + " is a NUL byte (a .gltf file is JSON text)");
    }
    bool ok = false;
    try {
        ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, name) : loader.LoadASCIIFromFile(&model, &err, &warn, name);
    } catch (const std::bad_alloc&) {
        throw GltfError(name + ": cannot parse: not enough memory");
    } catch (const std::exception& e) {
        throw GltfError(name + ": cannot parse: " + e.what());
    }
    if (!ok) {
        err = withoutTrailingNewlines(err);
        if (err.rfind("[json.exception.", 0) == 0 && err.find("] ") != std::string::npos)
            err.erase(0, err.find("] ") + 2);   // nlohmann's exception id, not for readers
        throw GltfError(name + ": " + (err.empty() ? std::string("cannot parse") : err));
    }
    GltfAsset asset;
    Mesh& mesh = asset.mesh;
    Reader reader{model, name, mesh, false, {}};
    if (model.scenes.empty()) {
        for (std::size_t i = 0; i < model.nodes.size(); ++i) reader.tree({int(i)}, "nodes");
    } else {
        const int s = model.defaultScene >= 0 ? model.defaultScene : 0;
        if (auto bad = badIndex(s, model.scenes.size(), "a scene")) throw GltfError(name + ": scene: " + *bad);
        reader.tree(model.scenes[std::size_t(s)].nodes, at("scenes", std::size_t(s)) + ".nodes");
    }
    // Normals and uvs are all-or-nothing per mesh (a primitive without them drops them all).
    if (mesh.normals.size() != mesh.positions.size()) mesh.normals.clear();
    if (mesh.uvs.size() != mesh.positions.size()) mesh.uvs.clear();
    for (const glm::vec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw GltfError(name + ": a vertex position is not a finite number");
    if (mesh.triangles.empty()) throw GltfError(name + ": contains no triangles");
    // Materials (only those the default scene's primitives use are read).
    std::vector<int> used(model.materials.size(), -1);
    MaterialReader materials{model, name, asset};
    for (int& t : mesh.triangleMaterials) {
        if (t < 0) continue;
        if (used[std::size_t(t)] < 0) {
            used[std::size_t(t)] = int(asset.materials.size());
            asset.materials.push_back(materials.material(std::size_t(t)));
        }
        t = used[std::size_t(t)];
    }
    if (!reader.anyMaterial) mesh.triangleMaterials.clear();
    for (const std::string& e : model.extensionsRequired)
        if (e != "KHR_materials_emissive_strength" && e != "KHR_materials_specular" && e != "KHR_materials_ior")
            asset.warnings.push_back(name + ": extensionsRequired: " + e + " is not supported; the file may look different");
    warn = withoutTrailingNewlines(warn);
    if (!warn.empty()) asset.warnings.push_back(name + ": " + warn);
    return asset;
}

Mesh loadGltf(const std::filesystem::path& file) {
    Mesh mesh = loadGltfAsset(file).mesh;
    mesh.triangleMaterials.clear();
    return mesh;
}

} // namespace raylab
