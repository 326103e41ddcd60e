#pragma once
// Runs the tracer's BVH traversal on the GPU (tests/support/trace_rays.comp) for a list of rays.
// Needs a current GL context.
#include "gl/shader_program.h"
#include "render/gpu_scene.h"
#include "render/shader_variant.h"
#include "shaders/include/bindings.glsl"

#include <glad/gl.h>

#include <bit>
#include <vector>

namespace raylab::test {

struct GpuTraceResult {
    float t;            // -1 for a miss
    unsigned instance;
    unsigned primitive;
    bool occluded;      // anything in (0, tMax)
};

struct TestRay {
    glm::vec4 origin;
    glm::vec4 dir;   // w = tMax for the occlusion query
};

// defines: the scene features (render/shader_variant.h featureDefines); every feature by default.
inline std::vector<GpuTraceResult> gpuTrace(const GpuScene& scene, const std::vector<TestRay>& rays,
                                            const ShaderDefines& defines = featureDefines(allFeatures())) {
    const ShaderProgram program = ShaderProgram::computeFromFile(
        std::filesystem::path(RAYLAB_SOURCE_DIR) / "tests/support/trace_rays.comp", defines);
    GLuint buffers[2];
    glCreateBuffers(2, buffers);
    glNamedBufferData(buffers[0], GLsizeiptr(rays.size() * sizeof(TestRay)), rays.data(), GL_STATIC_DRAW);
    glNamedBufferData(buffers[1], GLsizeiptr(rays.size() * sizeof(glm::vec4)), nullptr, GL_DYNAMIC_READ);
    scene.bind();
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_TEST_INPUT, buffers[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_TEST_OUTPUT, buffers[1]);
    glUseProgram(program.id());
    program.set("uRayCount", unsigned(rays.size()));
    glDispatchCompute(GLuint((rays.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> raw(rays.size());
    glGetNamedBufferSubData(buffers[1], 0, GLsizeiptr(raw.size() * sizeof(glm::vec4)), raw.data());
    glDeleteBuffers(2, buffers);
    std::vector<GpuTraceResult> out;
    for (const glm::vec4& r : raw)
        out.push_back({r.x, std::bit_cast<unsigned>(r.y), std::bit_cast<unsigned>(r.z), r.w != 0.0f});
    return out;
}

} // namespace raylab::test
