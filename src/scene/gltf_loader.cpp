#include "scene/gltf_loader.h"

#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>
#include <cstring>

namespace raylab {
namespace {

struct Reader {
    const tinygltf::Model& model;
    const std::string& name;
    Mesh& mesh;

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
    }
};

} // namespace

Mesh loadGltf(const std::filesystem::path& file) {
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
    Mesh mesh;
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
    return mesh;
}

} // namespace raylab
