#pragma once
// The BRDF explorer's model (the viewer's panel is a thin view of it): for a material and an
// incoming direction, the lobe f·cosθ in the plane of incidence, a hemisphere heat map, and a χ²
// test of the real GLSL sampler's directions (selftest/gpu_sampler.h) against the density
// bsdfPdf says it has. The maths is the tracer's own: shaders/include/bsdf.glsl, shared by C++
// and GLSL. Everything here but the sampling itself runs without GL.
#include "selftest/gpu_sampler.h"
#include "scene/scene.h"
#include "stats/chi_square.h"

#include "shaders/include/bsdf.glsl"

#include <glm/glm.hpp>

#include <vector>

namespace raylab {

struct LobeToggles {
    bool diffuse = true;        // off: albedo 0
    bool specular = true;       // off: f0 0 (the GGX layer vanishes)
    bool transmission = true;   // off: transmission 0 (no glass part)
};

// The material's BSDF as the tracer builds it (integrator.glsl materialBsdf), lobes switched off
// as asked, sampled as `render` says (render.diffuse_sampling, render.ggx_sampling). Untextured:
// the albedo is the material's constant.
glsl::BsdfParams explorerBsdf(const Material& m, const LobeToggles& lobes = {}, const RenderSettings& render = {});

// Local frame (+z the normal): θ from the normal, φ around it, degrees.
glm::vec3 directionFromAngles(float thetaDeg, float phiDeg);
glm::vec2 anglesFromDirection(glm::vec3 w);   // (θ, φ) in degrees, φ in [0, 360)

// f·|cosθi| along the plane of incidence: wi at angle α from +z, α in (−180°, 180°], positive
// towards the mirror side (α = −θo is wo itself, |α| > 90° is below the surface).
struct PolarPoint {
    float angleDeg = 0.0f;
    glm::vec3 fCos{0.0f};
};
std::vector<PolarPoint> polarCurve(const glsl::BsdfParams& m, glm::vec3 wo, int steps = 360);

// Equal-area map of a hemisphere onto the unit disk (Lambert's azimuthal projection scaled by
// 1/√2): |p| = r gives cosθ = 1 − r², so dω = 2 dA and equal disk areas hold equal solid angles.
glm::vec3 diskToDirection(glm::vec2 p, bool lower);
glm::vec2 directionToDisk(glm::vec3 w);   // of w's own hemisphere (sign of z)

// Luminance of f·|cosθi| (or the sampling pdf) on an n × n grid over each hemisphere's disk
// (row-major, +y up); cells whose centre lies outside the disk hold −1.
struct HemisphereMap {
    int n = 0;
    std::vector<float> upper;
    std::vector<float> lower;
    float maxValue = 0.0f;
};
enum class MapQuantity { FCos, Pdf };
HemisphereMap hemisphereMap(const glsl::BsdfParams& m, glm::vec3 wo, int n = 32, MapQuantity q = MapQuantity::FCos);

// χ² of sampled directions against the pdf, on 2·n·n disk cells (upper then lower hemisphere)
// plus one cell for samples the density does not describe (delta lobes and failed samples),
// whose expected count is N·(1 − ∫pdf). Pass when p ≥ alpha.
struct SamplerTest {
    int n = 0;
    std::vector<double> observed;   // 2·n·n + 1
    std::vector<double> expected;
    stats::ChiSquareResult chi2;
    double alpha = 0.01;
    bool pass = false;
    int samples = 0;
    int deltaOrNone = 0;           // samples in the last cell
    double pdfIntegral = 0.0;      // ∫ pdf over the sphere, numerically
    double maxPdfMismatch = 0.0;   // max |sample pdf − bsdfPdf(wi)| / bsdfPdf(wi) over non-delta samples
};
// Index of w's cell on the 2·n·n grid.
int diskCell(int n, glm::vec3 w);
SamplerTest testSampler(const glsl::BsdfParams& m, glm::vec3 wo, const std::vector<GpuSample>& samples, int n = 16,
                        double alpha = 0.01);

} // namespace raylab
