#pragma once
// Runs tests/support/bsdf_samples.comp: samples drawn by the real GLSL sampling code on the
// current GL context, read back for statistics on the CPU.
#include "gl/shader_program.h"
#include "shaders/include/bsdf.glsl"

#include <glad/gl.h>
#include <glm/glm.hpp>

#include <filesystem>
#include <vector>

namespace raylab::test {

struct GpuSample {
    glm::vec4 wiPdf;
    glm::vec4 weightLobe;
    glm::vec3 wi() const { return glm::vec3(wiPdf); }
    float pdf() const { return wiPdf.w; }
    glm::vec3 weight() const { return glm::vec3(weightLobe); }
    int lobe() const { return int(weightLobe.w) % 8; }
    bool delta() const { return int(weightLobe.w) >= 8; }
};

class GpuSampler {
public:
    GpuSampler()
        : program_(ShaderProgram::computeFromFile(std::filesystem::path(RAYLAB_SOURCE_DIR) / "tests" / "support" /
                                                  "bsdf_samples.comp")) {}

    std::vector<GpuSample> cosineHemisphere(unsigned count, unsigned seed) const { return run(0, count, seed, {}, {}); }

    std::vector<GpuSample> bsdf(const glsl::BsdfParams& m, glm::vec3 wo, unsigned count, unsigned seed) const {
        return run(1, count, seed, m, wo);
    }

    // Directions towards a sphere (centre, radius) seen from the origin.
    std::vector<GpuSample> sphereCone(glm::vec3 center, float radius, unsigned count, unsigned seed) const {
        program_.set("uSphereCenter", center);
        program_.set("uSphereRadius", radius);
        return run(2, count, seed, {}, {});
    }

    // Directions from the sky map of a scene uploaded and bound by a GpuScene, with the rotation
    // and mean weight uniforms the tracer would set.
    std::vector<GpuSample> skyMap(float rotationRadians, float meanWeight, unsigned count, unsigned seed) const {
        program_.set("uSkyRotation", rotationRadians);
        program_.set("uEnvMeanWeight", meanWeight);
        return run(3, count, seed, {}, {});
    }

    // Directions towards a triangle light (world-space vertices) seen from the origin, by area.
    std::vector<GpuSample> triangleLight(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, unsigned count, unsigned seed) const {
        program_.set("uTriangle0", p0);
        program_.set("uTriangle1", p1);
        program_.set("uTriangle2", p2);
        return run(4, count, seed, {}, {});
    }

    // Lights picked by light_selection.glsl from the alias table of a scene uploaded and bound by a
    // GpuScene: wiPdf.x is the index (−1 the sky), .y its probability. The counts and whether the
    // sky is a light are the uniforms the tracer would set.
    std::vector<GpuSample> lightSelection(int sphereLights, int triangleLights, bool skyIsLight, unsigned count,
                                          unsigned seed) const {
        program_.set("uLightCount", sphereLights);
        program_.set("uTriangleLightCount", triangleLights);
        program_.set("uSkyIsLight", int(skyIsLight));
        return run(5, count, seed, {}, {});
    }

private:
    std::vector<GpuSample> run(int mode, unsigned count, unsigned seed, const glsl::BsdfParams& m,
                               glm::vec3 wo) const {
        GLuint buffer = 0;
        glCreateBuffers(1, &buffer);
        glNamedBufferStorage(buffer, GLsizeiptr(count * sizeof(GpuSample)), nullptr, GL_MAP_READ_BIT);
        const ShaderProgram& p = program_;
        p.set("uCount", count);
        p.set("uSeed", seed);
        p.set("uMode", mode);
        p.set("uWo", wo);
        p.set("uAlbedo", m.albedo);
        p.set("uF0", m.f0);
        p.set("uAlpha", m.alpha);
        p.set("uTransmission", m.transmission);
        p.set("uIor", m.ior);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 7, buffer);
        glUseProgram(p.id());
        glDispatchCompute((count + 63) / 64, 1, 1);
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        std::vector<GpuSample> out(count);
        glGetNamedBufferSubData(buffer, 0, GLsizeiptr(count * sizeof(GpuSample)), out.data());
        glDeleteBuffers(1, &buffer);
        return out;
    }

    ShaderProgram program_;
};

} // namespace raylab::test
