// Checks of the cosine-hemisphere slot: its pdf pointwise, and its samples by the BRDF explorer's
// χ² test (inspect/brdf_explorer.h testSampler) against cos θ / π.
#include "exercise/check_support.h"

#include "inspect/brdf_explorer.h"

#include <cmath>
#include <numbers>
#include <random>

namespace raylab {
using namespace exercise;
namespace {

constexpr double kPi = std::numbers::pi;

} // namespace

CheckResult checkHemispherePdf(const ExerciseProbe& probe) {
    std::vector<ProbeInput> in;
    for (int i = 0; i <= 30; ++i) {
        const float c = -0.5f + 1.5f * float(i) / 30.0f;
        in.push_back({{glm::vec4(0.5f, 0.5f, c, 0.0f)}});
    }
    const auto out = probe.run(ProbeMode::Hemisphere, in);
    std::vector<double> got, want;
    Mistake noPi{"the pdf misses the 1/π: cos θ / π integrates to 1 over the hemisphere, cos θ to π", {}};
    Mistake uniform{"the pdf is the uniform hemisphere's 1/(2π), not cos θ / π", {}};
    Mistake below{"the pdf is negative below the surface: it must be 0 where cos θ ≤ 0", {}};
    Mistake twoPi{"the pdf divides by 2π: the hemisphere's solid angle, but ∫ cos θ dω = π", {}};
    for (const auto& x : in) {
        const double c = x.v[0].z;
        want.push_back(std::max(c, 0.0) / kPi);
        noPi.values.push_back(std::max(c, 0.0));
        uniform.values.push_back(c > 0.0 ? 0.5 / kPi : 0.0);
        below.values.push_back(c / kPi);
        twoPi.values.push_back(std::max(c, 0.0) / (2.0 * kPi));
    }
    for (const auto& y : out) got.push_back(y.b.x);
    const Comparison c = compare(got, want, 1e-4);
    CheckResult res{"hemisphere-pdf", c.wrong == 0, describe(c, "pdf values"), "", ""};
    if (!res.pass) {
        const std::string why = diagnose(got, {noPi, uniform, below, twoPi}, 1e-4);
        const auto i = std::size_t(c.firstWrong);
        res.message = why.empty() ? "pdf(cos θ = " + num(in[i].v[0].z) + ") should be " + num(want[i]) + ", got " + num(got[i])
                                  : "cosine hemisphere: " + why;
    }
    return res;
}

CheckResult checkHemisphereChi2(const ExerciseProbe& probe) {
    const int n = 200000;
    std::mt19937 rng(18);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<ProbeInput> in(n);
    for (auto& x : in) x.v[0] = glm::vec4(u(rng), u(rng), 1.0f, 0.0f);
    const auto out = probe.run(ProbeMode::Hemisphere, in);
    std::vector<GpuSample> samples;
    samples.reserve(n);
    int notUnit = 0;
    double meanCos = 0.0;
    for (const auto& y : out) {
        const glm::vec3 w(y.a);
        if (!(std::abs(glm::length(w) - 1.0f) < 1e-3f)) ++notUnit;
        meanCos += double(w.z) / n;
        // Every direction is counted: its cell says whether the density allows it.
        samples.push_back({glm::vec4(glm::normalize(w), 1.0f), glm::vec4(1.0f, 1.0f, 1.0f, float(glsl::LOBE_DIFFUSE))});
    }
    CheckResult res{"hemisphere-chi2", false, "", "", ""};
    if (notUnit > 0) {
        res.numbers = std::to_string(notUnit) + " of " + std::to_string(n) + " directions not of unit length";
        res.message = "cosine hemisphere: the directions must be unit vectors: z = √(1 − x² − y²) lifts the disk point "
                      "onto the hemisphere";
        return res;
    }
    const glsl::BsdfParams lambert(glm::vec3(1.0f), glm::vec3(0.0f), 1.0f, 0.0f, 1.5f);
    const SamplerTest t = testSampler(lambert, glm::vec3(0.0f, 0.0f, 1.0f), samples);
    res.pass = t.pass;
    res.numbers = "χ² " + num(t.chi2.statistic) + ", " + std::to_string(t.chi2.dof) + " dof, p = " + num(t.chi2.pValue) +
                  " (α " + num(t.alpha) + ", " + std::to_string(n) + " samples), mean cos θ " + num(meanCos) +
                  " (cos θ / π: 2/3)";
    if (res.pass) return res;
    // The mean of cos θ tells the usual mistakes apart: 2/3 for cos θ / π, 1/2 for a uniform
    // hemisphere, π/4 for a disk radius u instead of √u (points crowd the centre).
    const double sigma = 4.0 / std::sqrt(double(n));
    if (t.chi2.sampleInZeroCell)
        res.message = "cosine hemisphere: some directions point below the surface (z < 0)";
    else if (std::abs(meanCos - 0.5) < sigma)
        res.message = "cosine hemisphere: the directions are uniform over the hemisphere (mean cos θ 1/2), not cosine-weighted";
    else if (std::abs(meanCos - kPi / 4.0) < sigma)
        res.message = "cosine hemisphere: the disk points crowd its centre: a uniform disk needs radius √u, not u";
    else
        res.message = "cosine hemisphere: the directions do not follow cos θ / π (χ² p = " + num(t.chi2.pValue) + ")";
    return res;
}

} // namespace raylab
