#include "scene/gltf_loader.h"

#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace raylab {
namespace {

struct Reader {
    const tinygltf::Model& model;
    const std::string& name;
    Mesh& mesh;
    bool anyMaterial = false;   // some primitive names a material

    [[noreturn]] void fail(const std::string& what) const { throw GltfError(name + ": " + what); }

    // Element i of an accessor as up to 4 doubles (normalised integers are scaled to [0, 1]).
    std::vector<double> read(int accessorIndex, std::size_t i) const {
        if (accessorIndex < 0 || std::size_t(accessorIndex) >= model.accessors.size()) fail("bad accessor index");
        const tinygltf::Accessor& a = model.accessors[std::size_t(accessorIndex)];
        if (a.sparse.isSparse) fail("sparse accessors are not supported");
        if (a.bufferView < 0 || std::size_t(a.bufferView) >= model.bufferViews.size()) fail("accessor without data");
        const tinygltf::BufferView& v = model.bufferViews[std::size_t(a.bufferView)];
        const tinygltf::Buffer& b = model.buffers.at(std::size_t(v.buffer));
        const int stride = a.ByteStride(v);
        const int n = tinygltf::GetNumComponentsInType(static_cast<std::uint32_t>(a.type));
        const int size = tinygltf::GetComponentSizeInBytes(static_cast<std::uint32_t>(a.componentType));
        if (stride <= 0 || n <= 0 || size <= 0) fail("malformed accessor");
        const std::size_t start = v.byteOffset + a.byteOffset + i * std::size_t(stride);
        if (start + std::size_t(n * size) > b.data.size()) fail("accessor reads past the end of its buffer");
        std::vector<double> out(static_cast<std::size_t>(n));
        for (int k = 0; k < n; ++k) {
            const unsigned char* p = b.data.data() + start + std::size_t(k * size);
            double x = 0.0;
            switch (a.componentType) {
            case TINYGLTF_COMPONENT_TYPE_FLOAT: { float f; std::memcpy(&f, p, 4); x = f; break; }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: x = *p; if (a.normalized) x /= 255.0; break;
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: { std::uint16_t s; std::memcpy(&s, p, 2); x = s; if (a.normalized) x /= 65535.0; break; }
            case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: { std::uint32_t u; std::memcpy(&u, p, 4); x = u; break; }
            default: fail("unsupported component type " + std::to_string(a.componentType));
            }
            out[std::size_t(k)] = x;
        }
        return out;
    }

    std::size_t count(int accessorIndex) const {
        if (accessorIndex < 0 || std::size_t(accessorIndex) >= model.accessors.size()) fail("bad accessor index");
        return model.accessors[std::size_t(accessorIndex)].count;
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

    void node(int index, const glm::mat4& parent, int depth) {
        if (index < 0 || std::size_t(index) >= model.nodes.size()) fail("bad node index");
        if (depth > 64) fail("the node hierarchy is deeper than 64 (a cycle?)");
        const tinygltf::Node& n = model.nodes[std::size_t(index)];
        const glm::mat4 world = parent * localMatrix(n);
        if (n.mesh >= 0) {
            if (std::size_t(n.mesh) >= model.meshes.size()) fail("bad mesh index");
            for (const tinygltf::Primitive& p : model.meshes[std::size_t(n.mesh)].primitives) primitive(p, world);
        }
        for (int c : n.children) node(c, world, depth + 1);
    }

    void primitive(const tinygltf::Primitive& p, const glm::mat4& world) {
        if (p.mode != TINYGLTF_MODE_TRIANGLES && p.mode != -1) return;   // points and lines: skipped
        const auto pos = p.attributes.find("POSITION");
        if (pos == p.attributes.end()) fail("a primitive has no POSITION");
        const auto nrm = p.attributes.find("NORMAL");
        const auto uv = p.attributes.find("TEXCOORD_0");
        const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(world)));
        const unsigned base = unsigned(mesh.positions.size());
        const std::size_t n = count(pos->second);
        for (std::size_t i = 0; i < n; ++i) {
            const std::vector<double> v = read(pos->second, i);
            mesh.positions.push_back(glm::vec3(world * glm::vec4(float(v[0]), float(v[1]), float(v[2]), 1.0f)));
            if (nrm != p.attributes.end()) {
                const std::vector<double> w = read(nrm->second, i);
                mesh.normals.push_back(glm::normalize(normalMatrix * glm::vec3(float(w[0]), float(w[1]), float(w[2]))));
            }
            if (uv != p.attributes.end()) {
                const std::vector<double> t = read(uv->second, i);
                mesh.uvs.emplace_back(float(t[0]), 1.0f - float(t[1]));   // glTF's v runs downwards
            }
        }
        const std::size_t firstTriangle = mesh.triangles.size();
        if (p.indices >= 0) {
            const std::size_t m = count(p.indices);
            for (std::size_t i = 0; i + 2 < m; i += 3) {
                glm::uvec3 t;
                for (int k = 0; k < 3; ++k) {
                    const double index = read(p.indices, i + std::size_t(k))[0];
                    if (index >= double(n)) fail("a triangle index is out of range");
                    t[k] = base + unsigned(index);
                }
                mesh.triangles.push_back(t);
            }
        } else {
            for (unsigned i = 0; i + 2 < n; i += 3) mesh.triangles.emplace_back(base + i, base + i + 1, base + i + 2);
        }
        if (p.material >= 0 && std::size_t(p.material) >= model.materials.size()) fail("bad material index");
        anyMaterial |= p.material >= 0;
        mesh.triangleMaterials.resize(firstTriangle, -1);
        mesh.triangleMaterials.resize(mesh.triangles.size(), p.material);
    }
};

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
        tex.file = key;
        if (t.sampler >= 0) {
            if (std::size_t(t.sampler) >= model.samplers.size()) fail(where, tp + ": bad sampler index");
            const tinygltf::Sampler& s = model.samplers[std::size_t(t.sampler)];
            tex.wrapU = wrapMode(s.wrapS);
            tex.wrapV = wrapMode(s.wrapT);
        }
        asset.textures.push_back(std::move(tex));
        return int(asset.textures.size() - 1);
    }

    static float clamp01(double v) { return float(std::min(1.0, std::max(0.0, v))); }

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
        // glTF's dielectrics reflect 4% at normal incidence; metals take the base colour as f0.
        m.f0 = glm::vec3(0.04f);
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
        if (g.alphaMode != "OPAQUE" && !g.alphaMode.empty())
            asset.warnings.push_back(name + ": " + mp + ".alphaMode: " + g.alphaMode +
                                     " is ignored; the material is opaque");
        if (g.occlusionTexture.index >= 0)
            asset.warnings.push_back(name + ": " + mp + ".occlusionTexture is ignored (a path tracer finds occlusion itself)");
        return m;
    }
};

} // namespace

GltfAsset loadGltfAsset(const std::filesystem::path& file) {
    const std::string name = file.string();
    if (!std::filesystem::is_regular_file(file)) throw GltfError(name + ": cannot read: no such file");
    tinygltf::Model model;
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    const bool binary = file.extension() == ".glb" || file.extension() == ".GLB";
    const bool ok = binary ? loader.LoadBinaryFromFile(&model, &err, &warn, name)
                           : loader.LoadASCIIFromFile(&model, &err, &warn, name);
    if (!ok) {
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
        throw GltfError(name + ": " + (err.empty() ? std::string("cannot parse") : err));
    }
    GltfAsset asset;
    Mesh& mesh = asset.mesh;
    Reader reader{model, name, mesh};
    if (model.scenes.empty()) {
        for (std::size_t i = 0; i < model.nodes.size(); ++i) reader.node(int(i), glm::mat4(1.0f), 0);
    } else {
        const std::size_t s = model.defaultScene >= 0 ? std::size_t(model.defaultScene) : 0;
        if (s >= model.scenes.size()) throw GltfError(name + ": bad default scene");
        for (int n : model.scenes[s].nodes) reader.node(n, glm::mat4(1.0f), 0);
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
        if (e != "KHR_materials_emissive_strength")
            asset.warnings.push_back(name + ": extensionsRequired: " + e + " is not supported; the file may look different");
    if (!warn.empty()) {
        while (!warn.empty() && (warn.back() == '\n' || warn.back() == '\r')) warn.pop_back();
        asset.warnings.push_back(name + ": " + warn);
    }
    return asset;
}

Mesh loadGltf(const std::filesystem::path& file) {
    Mesh mesh = loadGltfAsset(file).mesh;
    mesh.triangleMaterials.clear();
    return mesh;
}

} // namespace raylab
