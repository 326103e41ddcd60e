#include "render/few_objects.h"

#include <algorithm>

namespace raylab {

glsl::FewObjectsBlock fewObjectsBlock(const SceneGeometry& top) {
    glsl::FewObjectsBlock block{};
    const std::size_t max = std::size_t(glsl::FEW_OBJECTS_MAX);
    for (std::size_t i = 0; i < std::min(top.instances.size(), max); ++i) {
        const glsl::GpuInstance& inst = top.instances[i];
        const float mesh = inst.info.x == glsl::INSTANCE_MESH ? 1.0f : 0.0f;
        block.boxMin[i] = glm::vec4(glm::vec3(inst.worldMin), mesh);
        block.boxMax[i] = glm::vec4(glm::vec3(inst.worldMax), 0.0f);
        if (mesh != 0.0f)
            block.triangles[i] = glm::uvec4(glsl::instanceFirstTriangle(inst), glsl::instanceTriangleCount(inst), 0u, 0u);
    }
    std::copy_n(top.spheres.begin(), std::min(top.spheres.size(), max), block.spheres);
    return block;
}

} // namespace raylab
