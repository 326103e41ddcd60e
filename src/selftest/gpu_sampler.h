#pragma once
// Runs shaders/entry/bsdf_samples.comp: samples drawn by the real GLSL sampling code on the
// current GL context, read back for statistics on the CPU (the tests' χ² tests and the viewer's
// self-test on the user's own driver). Needs a current GL 4.5 context.
#include "gl/shader_program.h"
#include "shaders/include/bsdf.glsl"
#include "shaders/include/tracer_params.glsl"

#include <glm/glm.hpp>

#include <vector>

namespace raylab {

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
    GpuSampler();   // throws ShaderError
    ~GpuSampler();
    GpuSampler(const GpuSampler&) = delete;
    GpuSampler& operator=(const GpuSampler&) = delete;

    std::vector<GpuSample> cosineHemisphere(unsigned count, unsigned seed) const;
    std::vector<GpuSample> bsdf(const glsl::BsdfParams& m, glm::vec3 wo, unsigned count, unsigned seed) const;
    // Directions towards a sphere (centre, radius) seen from the origin.
    std::vector<GpuSample> sphereCone(glm::vec3 center, float radius, unsigned count, unsigned seed) const;
    // Directions from the sky map of a scene uploaded and bound by a GpuScene, with the rotation
    // and mean weight the tracer would set.
    std::vector<GpuSample> skyMap(float rotationRadians, float meanWeight, unsigned count, unsigned seed) const;
    // Directions towards a triangle light (world-space vertices) seen from the origin, as the tracer
    // samples them (triangle_light.glsl): wiPdf the direction and its pdf, weightLobe.x the pdf a
    // BSDF sample meeting the same point gets, .yzw that point.
    std::vector<GpuSample> triangleLight(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, unsigned count, unsigned seed) const;
    // Lights picked by light_selection.glsl from the alias table of a scene uploaded and bound by a
    // GpuScene: wiPdf.x is the index (−1 the sky), .y its probability, .w the number that made the
    // pick, rescaled within it. The counts and whether the sky is a light are the parameters the
    // tracer would set.
    std::vector<GpuSample> lightSelection(int sphereLights, int triangleLights, bool skyIsLight, unsigned count,
                                          unsigned seed) const;

private:
    std::vector<GpuSample> run(int mode, unsigned count, unsigned seed, const glsl::BsdfParams& m, glm::vec3 wo) const;
    ShaderProgram program_;
    // The tracer's parameter block, of which the harness fills the fields its modes read; it keeps
    // them from call to call.
    mutable glsl::TracerParams params_{};
    unsigned paramsBuffer_ = 0;
};

} // namespace raylab
