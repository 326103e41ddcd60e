#pragma once
// The CPU side of shaders/include/texture.glsl's one external: `vec4 texelAt(uint i)` reads the
// texels a caller points `cpuTexels` at. One definition for every file that includes texture.glsl:
// two inline texelAt with different bodies in one program break the one-definition rule (the
// linker keeps one, and the other reads through a null pointer).
#include <glm/glm.hpp>

#include <vector>

namespace raylab::glsl {
using namespace glm;
inline thread_local const std::vector<glm::vec4>* cpuTexels = nullptr;
inline vec4 texelAt(uint i) { return (*cpuTexels)[i]; }
} // namespace raylab::glsl
