#pragma once
// Runs tests/support/lens_samples.comp: lens positions drawn by the tracer's own thin-lens code on
// the current GL context. Needs a current GL 4.5 context.
#include "gl/shader_program.h"
#include "shaders/include/bindings.glsl"

#include <glad/gl.h>
#include <glm/glm.hpp>

#include <filesystem>
#include <vector>

namespace raylab::test {

// xy: the ray origin on the lens over the lens radius (in the unit disk); z: its offset along the
// view (0: on the lens plane); w: |ray direction| − 1.
inline std::vector<glm::vec4> gpuLensSamples(glm::vec3 position, glm::vec3 lookAt, float lensRadius,
                                             float focusDistance, unsigned count, unsigned seed) {
    const ShaderProgram program =
        ShaderProgram::computeFromFile(std::filesystem::path(RAYLAB_SOURCE_DIR) / "tests/support/lens_samples.comp");
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(count * sizeof(glm::vec4)), nullptr, GL_MAP_READ_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_TEST_OUTPUT, buffer);
    glUseProgram(program.id());
    program.set("uCount", count);
    program.set("uSeed", seed);
    program.set("uPosition", position);
    program.set("uLookAt", lookAt);
    program.set("uLensRadius", lensRadius);
    program.set("uFocusDistance", focusDistance);
    glDispatchCompute((count + 63) / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> out(count);
    glGetNamedBufferSubData(buffer, 0, GLsizeiptr(count * sizeof(glm::vec4)), out.data());
    glDeleteBuffers(1, &buffer);
    return out;
}

} // namespace raylab::test
