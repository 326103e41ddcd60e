#include "selftest/gpu_sampler.h"

#include "render/shader_variant.h"
#include "shaders/include/bindings.glsl"

#include <glad/gl.h>

namespace raylab {

GpuSampler::GpuSampler() : program_(ShaderProgram::compute("entry/bsdf_samples.comp", featureDefines(allFeatures()))) {
    glCreateBuffers(1, &paramsBuffer_);
    glNamedBufferStorage(paramsBuffer_, sizeof(params_), &params_, GL_DYNAMIC_STORAGE_BIT);
}

GpuSampler::~GpuSampler() { glDeleteBuffers(1, &paramsBuffer_); }

std::vector<GpuSample> GpuSampler::cosineHemisphere(unsigned count, unsigned seed) const { return run(0, count, seed, {}, {}); }

std::vector<GpuSample> GpuSampler::bsdf(const glsl::BsdfParams& m, glm::vec3 wo, unsigned count, unsigned seed) const {
    return run(1, count, seed, m, wo);
}

std::vector<GpuSample> GpuSampler::sphereCone(glm::vec3 center, float radius, unsigned count, unsigned seed) const {
    program_.set("uSphereCenter", center);
    program_.set("uSphereRadius", radius);
    return run(2, count, seed, {}, {});
}

std::vector<GpuSample> GpuSampler::skyMap(float rotationRadians, float meanWeight, unsigned count, unsigned seed) const {
    params_.skyRotation = rotationRadians;
    params_.envMeanWeight = meanWeight;
    return run(3, count, seed, {}, {});
}

std::vector<GpuSample> GpuSampler::triangleLight(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, unsigned count,
                                                 unsigned seed) const {
    program_.set("uTriangle0", p0);
    program_.set("uTriangle1", p1);
    program_.set("uTriangle2", p2);
    return run(4, count, seed, {}, {});
}

std::vector<GpuSample> GpuSampler::lightSelection(int sphereLights, int triangleLights, bool skyIsLight,
                                                  unsigned count, unsigned seed) const {
    params_.lightCount = sphereLights;
    params_.triangleLightCount = triangleLights;
    params_.skyIsLight = skyIsLight;
    return run(5, count, seed, {}, {});
}

std::vector<GpuSample> GpuSampler::run(int mode, unsigned count, unsigned seed, const glsl::BsdfParams& m,
                                       glm::vec3 wo) const {
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(count * sizeof(GpuSample)), nullptr, GL_MAP_READ_BIT);
    const ShaderProgram& p = program_;
    p.set("uCount", count);
    params_.seed = seed;
    glNamedBufferSubData(paramsBuffer_, 0, sizeof(params_), &params_);
    glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_TRACER_PARAMS_UBO, paramsBuffer_);
    p.set("uMode", mode);
    p.set("uWo", wo);
    p.set("uAlbedo", m.albedo);
    p.set("uF0", m.f0);
    p.set("uAlpha", m.alpha);
    p.set("uTransmission", m.transmission);
    p.set("uIor", m.ior);
    p.set("uDiffuseSampling", m.diffuseSampling);
    p.set("uGgxSampling", m.ggxSampling);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_BSDF_SAMPLES, buffer);
    glUseProgram(p.id());
    glDispatchCompute((count + 63) / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<GpuSample> out(count);
    glGetNamedBufferSubData(buffer, 0, GLsizeiptr(count * sizeof(GpuSample)), out.data());
    glDeleteBuffers(1, &buffer);
    return out;
}

} // namespace raylab
