#pragma once
// A few small meshes placed by transforms of their own are uploaded with those transforms applied
// to their vertices (Cycles does the same for objects that are not instanced), so every mesh is
// placed by the identity and the tracer transforms neither rays nor hits (RAYLAB_MESHES_IN_WORLD;
// bench/mesh_rays.md, "Mesh transforms baked into positions").
#include "scene/scene.h"

#include <glm/glm.hpp>

namespace raylab {

// Whether the GPU scene bakes the meshes' transforms: the scene has meshes, every mesh is small and
// the top level is a plain loop (render/shader_variant.h). Moving a mesh then rebuilds its few
// triangles instead of its instance row.
bool bakesMeshTransforms(const Scene& scene);

// The scene with each mesh's transform applied to its positions (T·Rz·Ry·Rx·S, in double, less
// `origin`: the GPU's camera-relative origin, so far from the world origin the vertices keep their
// precision) and normals (the inverse transpose, renormalised), and every mesh's transform the
// identity. The textures are not copied: the copy is for the geometry and the light list only.
Scene withMeshTransformsBaked(const Scene& scene, const glm::dvec3& origin = glm::dvec3(0.0));

} // namespace raylab
