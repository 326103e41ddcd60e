#pragma once
// One-click self-test on the user's own GL driver (the viewer's Self-test panel): the white
// furnace through the real tracer, and χ² tests of the real GLSL samplers (cosine hemisphere,
// GGX visible normals at a few (α, θ), rough glass, the sphere light's cone) against their pdfs.
// Needs a current GL 4.5 context.
#include "shaders/include/bsdf.glsl"

#include <functional>
#include <string>
#include <vector>

namespace raylab {

struct SelfTestResult {
    std::string name;          // "furnace", "cosine hemisphere", "GGX a=0.2 cos=0.5"
    bool pass = false;
    std::string kind;          // "max deviation" or "chi2"
    double statistic = 0.0;    // χ² value, or the furnace's largest |pixel − expected|
    int dof = 0;               // χ² degrees of freedom (0 for the furnace)
    double pValue = 1.0;       // χ²: P(χ² ≥ statistic); the furnace: 1 or 0
    double alpha = 0.0;        // χ²: the per-test significance (Šidák over the family); furnace: the tolerance
    std::string detail;        // what went wrong, if anything
};

struct SelfTestReport {
    std::vector<SelfTestResult> results;
    double seconds = 0.0;
    std::string driver;        // GL_RENDERER / GL_VERSION
    bool pass() const;
};

struct SelfTestOptions {
    unsigned samples = 200000;   // per χ² test
    unsigned seed = 7;
    double alpha = 0.01;         // family-wise significance of the χ² tests (Šidák-corrected)
    // The pdfs the samples are tested against; the defaults are the shared C++/GLSL code's own
    // (what the tracer divides by). Tests pass wrong ones to check that the self-test can fail.
    std::function<double(float cosTheta)> cosinePdf;
    std::function<double(const glsl::BsdfParams&, glm::vec3 wo, glm::vec3 wi)> bsdfPdf;
    // Solid-angle density of the sphere light's cone sampler seen from the origin.
    std::function<double(glm::vec3 center, float radius)> sphereConePdf;
};

// Runs every test; exceptions (a shader that fails to compile) become a failed result.
SelfTestReport runSelfTest(const SelfTestOptions& options = {});

// One line per result: "PASS furnace: max deviation 2.4e-07 (tolerance 1e-05)".
std::string describe(const SelfTestResult& r);

} // namespace raylab
