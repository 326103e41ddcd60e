#include "scene/obj_loader.h"

#include <tiny_obj_loader.h>

#include <cmath>
#include <map>
#include <tuple>

namespace raylab {

Mesh loadObj(const std::filesystem::path& file) {
    const std::string name = file.string();
    if (!std::filesystem::is_regular_file(file)) throw ObjError(name + ": cannot read: no such file");
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(name, config)) {
        std::string err = reader.Error();
        while (!err.empty() && (err.back() == '\n' || err.back() == '\r')) err.pop_back();
        throw ObjError(name + ": " + (err.empty() ? std::string("cannot parse") : err));
    }
    const tinyobj::attrib_t& a = reader.GetAttrib();
    Mesh mesh;
    std::map<std::tuple<int, int, int>, unsigned> merged;   // (v, vn, vt) → vertex
    bool anyNormal = false, anyUv = false, missingNormal = false, missingUv = false;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        for (const tinyobj::index_t& i : shape.mesh.indices) {
            anyNormal |= i.normal_index >= 0;
            anyUv |= i.texcoord_index >= 0;
            missingNormal |= i.normal_index < 0;
            missingUv |= i.texcoord_index < 0;
        }
    }
    const bool useNormals = anyNormal && !missingNormal;   // all or nothing, per mesh
    const bool useUvs = anyUv && !missingUv;
    for (const tinyobj::shape_t& shape : reader.GetShapes()) {
        const auto& idx = shape.mesh.indices;
        for (std::size_t f = 0; f + 2 < idx.size(); f += 3) {
            glm::uvec3 tri;
            for (int k = 0; k < 3; ++k) {
                const tinyobj::index_t& i = idx[f + std::size_t(k)];
                const auto key = std::make_tuple(i.vertex_index, useNormals ? i.normal_index : -1,
                                                 useUvs ? i.texcoord_index : -1);
                auto [it, inserted] = merged.try_emplace(key, unsigned(mesh.positions.size()));
                if (inserted) {
                    const std::size_t v = std::size_t(i.vertex_index);
                    if (3 * v + 2 >= a.vertices.size())
                        throw ObjError(name + ": face refers to vertex " + std::to_string(v + 1) +
                                       ", which does not exist");
                    mesh.positions.emplace_back(a.vertices[3 * v], a.vertices[3 * v + 1], a.vertices[3 * v + 2]);
                    if (useNormals) {
                        const std::size_t n = std::size_t(i.normal_index);
                        mesh.normals.emplace_back(a.normals[3 * n], a.normals[3 * n + 1], a.normals[3 * n + 2]);
                    }
                    if (useUvs) {
                        const std::size_t t = std::size_t(i.texcoord_index);
                        mesh.uvs.emplace_back(a.texcoords[2 * t], a.texcoords[2 * t + 1]);
                    }
                }
                tri[k] = it->second;
            }
            mesh.triangles.push_back(tri);
        }
    }
    for (const glm::vec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            throw ObjError(name + ": a vertex position is not a finite number");
    if (mesh.triangles.empty()) throw ObjError(name + ": contains no faces");
    return mesh;
}

} // namespace raylab
