#include "inspect/brdf_explorer.h"

#include "shaders/include/ggx.glsl"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace raylab {
namespace {

constexpr double kPi = std::numbers::pi;

float luminance(glm::vec3 c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; }

} // namespace

glsl::BsdfParams explorerBsdf(const Material& m, const LobeToggles& lobes, const RenderSettings& render) {
    // Untextured, so metallic applies as the scene upload bakes it (render/gpu_scene.cpp).
    glsl::BsdfParams p = glsl::bsdfWithMetallic({m.albedo, m.f0, glsl::ggxAlpha(m.roughness), m.transmission, m.ior,
                                                 int(render.diffuseSampling), int(render.ggxSampling)},
                                                m.metallic);
    if (!lobes.diffuse) p.albedo = glm::vec3(0.0f);
    if (!lobes.specular) p.f0 = glm::vec3(0.0f);
    if (!lobes.transmission) p.transmission = 0.0f;
    return p;
}

glm::vec3 directionFromAngles(float thetaDeg, float phiDeg) {
    const float t = glm::radians(thetaDeg), p = glm::radians(phiDeg);
    return {std::sin(t) * std::cos(p), std::sin(t) * std::sin(p), std::cos(t)};
}

glm::vec2 anglesFromDirection(glm::vec3 w) {
    w = glm::normalize(w);
    float phi = glm::degrees(std::atan2(w.y, w.x));
    if (phi < 0.0f) phi += 360.0f;
    return {glm::degrees(std::acos(std::clamp(w.z, -1.0f, 1.0f))), phi};
}

std::vector<PolarPoint> polarCurve(const glsl::BsdfParams& m, glm::vec3 wo, int steps) {
    const float phiO = std::atan2(wo.y, wo.x);
    // The plane's in-surface axis; normal incidence has none: take +x.
    const glm::vec2 axis = wo.x * wo.x + wo.y * wo.y > 1e-12f ? glm::vec2(std::cos(phiO), std::sin(phiO)) : glm::vec2(1, 0);
    std::vector<PolarPoint> out;
    out.reserve(std::size_t(steps) + 1);
    for (int i = 0; i <= steps; ++i) {
        const float a = glm::radians(-180.0f + 360.0f * float(i) / float(steps));
        // Positive α towards the mirror side, away from wo's azimuth.
        const glm::vec3 wi(-std::sin(a) * axis.x, -std::sin(a) * axis.y, std::cos(a));
        out.push_back({glm::degrees(a), glsl::bsdfEval(m, wo, wi)});
    }
    return out;
}

glm::vec3 diskToDirection(glm::vec2 p, bool lower) {
    const float r2 = std::min(glm::dot(p, p), 1.0f);
    const float z = 1.0f - r2;
    const glm::vec2 xy = p * std::sqrt(std::max(2.0f - r2, 0.0f));
    return {xy.x, xy.y, lower ? -z : z};
}

glm::vec2 directionToDisk(glm::vec3 w) {
    w = glm::normalize(w);
    const float r = std::sqrt(std::max(1.0f - std::abs(w.z), 0.0f));   // r² = 1 − |cosθ|
    const float s = std::sqrt(w.x * w.x + w.y * w.y);
    if (s <= 0.0f) return {0.0f, 0.0f};
    return glm::vec2(w.x, w.y) * (r / s);
}

HemisphereMap hemisphereMap(const glsl::BsdfParams& m, glm::vec3 wo, int n, MapQuantity q) {
    const auto value = [&](glm::vec3 wi) {
        return q == MapQuantity::Pdf ? glsl::bsdfPdf(m, wo, wi) : luminance(glsl::bsdfEval(m, wo, wi));
    };
    HemisphereMap map;
    map.n = n;
    map.upper.assign(std::size_t(n * n), -1.0f);
    map.lower.assign(std::size_t(n * n), -1.0f);
    for (int row = 0; row < n; ++row)
        for (int col = 0; col < n; ++col) {
            const glm::vec2 p(-1.0f + 2.0f * (float(col) + 0.5f) / float(n), 1.0f - 2.0f * (float(row) + 0.5f) / float(n));
            if (glm::dot(p, p) > 1.0f) continue;
            const std::size_t i = std::size_t(row * n + col);
            map.upper[i] = value(diskToDirection(p, false));
            map.lower[i] = value(diskToDirection(p, true));
            map.maxValue = std::max({map.maxValue, map.upper[i], map.lower[i]});
        }
    return map;
}

int diskCell(int n, glm::vec3 w) {
    const glm::vec2 p = directionToDisk(w);
    const int col = std::clamp(int((p.x + 1.0f) * 0.5f * float(n)), 0, n - 1);
    const int row = std::clamp(int((1.0f - p.y) * 0.5f * float(n)), 0, n - 1);
    return (w.z < 0.0f ? n * n : 0) + row * n + col;
}

namespace {

// ∫ f dω over the square of side s centred at (x, y) on the disk (dω = 2 dA), given f there: the
// midpoints of its quarters, each quarter again where they disagree with the whole (5 levels).
template <class F>
double integrateSquare(const F& f, double x, double y, double s, double mid, int depth) {
    const double q = s / 4.0;
    const double v[4] = {f(x - q, y - q), f(x + q, y - q), f(x - q, y + q), f(x + q, y + q)};
    const double coarse = mid * s * s * 2.0;
    const double fine = (v[0] + v[1] + v[2] + v[3]) * (s * s / 4.0) * 2.0;
    if (depth >= 5 || std::abs(fine - coarse) <= 1e-7) return fine;
    return integrateSquare(f, x - q, y - q, s / 2.0, v[0], depth + 1) + integrateSquare(f, x + q, y - q, s / 2.0, v[1], depth + 1) +
           integrateSquare(f, x - q, y + q, s / 2.0, v[2], depth + 1) + integrateSquare(f, x + q, y + q, s / 2.0, v[3], depth + 1);
}

} // namespace

SamplerTest testSampler(const glsl::BsdfParams& m, glm::vec3 wo, const std::vector<GpuSample>& samples, int n,
                        double alpha) {
    SamplerTest t;
    t.n = n;
    t.alpha = alpha;
    t.samples = int(samples.size());
    const std::size_t cells = std::size_t(2 * n * n);
    t.observed.assign(cells + 1, 0.0);
    t.expected.assign(cells + 1, 0.0);
    for (const GpuSample& s : samples) {
        if (s.delta() || s.lobe() == glsl::LOBE_NONE || !(s.pdf() > 0.0f)) {
            ++t.deltaOrNone;
            t.observed[cells] += 1.0;
            continue;
        }
        t.observed[std::size_t(diskCell(n, s.wi()))] += 1.0;
        const float pdf = glsl::bsdfPdf(m, wo, s.wi());
        if (pdf > 0.0f) t.maxPdfMismatch = std::max(t.maxPdfMismatch, double(std::abs(s.pdf() - pdf) / pdf));
    }
    // N × ∫cell pdf dω (dω = 2 dA on the disk): the midpoint rule on k × k sub-cells, each refined
    // where it disagrees with its four quarters, so that a narrow lobe at a grazing angle, a few
    // sub-cells wide, is integrated as well as a broad one.
    const int k = 12;
    const double N = double(samples.size());
    for (int h = 0; h < 2; ++h) {
        const auto pdfAt = [&](double x, double y) {
            const glm::vec2 p{float(x), float(y)};
            return glm::dot(p, p) > 1.0f ? 0.0 : double(glsl::bsdfPdf(m, wo, diskToDirection(p, h == 1)));
        };
        const double sub = 2.0 / n / k;
        for (int row = 0; row < n; ++row)
            for (int col = 0; col < n; ++col) {
                double integral = 0.0;
                for (int i = 0; i < k; ++i)
                    for (int j = 0; j < k; ++j) {
                        const double x = -1.0 + 2.0 * (col + (j + 0.5) / k) / n;
                        const double y = 1.0 - 2.0 * (row + (i + 0.5) / k) / n;
                        integral += integrateSquare(pdfAt, x, y, sub, pdfAt(x, y), 0);
                    }
                t.pdfIntegral += integral;
                t.expected[std::size_t(h * n * n + row * n + col)] = N * integral;
            }
    }
    t.expected[cells] = N * std::max(0.0, 1.0 - t.pdfIntegral);
    t.chi2 = stats::chiSquareTest(t.observed, t.expected);
    t.pass = !t.chi2.sampleInZeroCell && t.chi2.pValue >= alpha;
    return t;
}

} // namespace raylab
