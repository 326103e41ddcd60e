#include "selftest/self_test.h"

#include "shaders/include/light_sampling.glsl"

#include "render/path_tracer.h"
#include "render/progressive_render.h"
#include "selftest/gpu_sampler.h"
#include "selftest/lobe_grid.h"
#include "stats/chi_square.h"

#include <glad/gl.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

namespace raylab {
namespace {

// The white furnace (scenes/furnace.json): a Lambertian sphere of albedo 0.5 filling the image in
// a constant sky of radiance 1. A convex sphere cannot see itself, so every camera path scatters
// once and reaches the sky: every pixel is 0.5 exactly, at any sample count.
SelfTestResult furnace() {
    Scene s;
    s.camera.position = glm::vec3(0, 0, 1.5f);
    s.camera.lookAt = glm::vec3(0.0f);
    s.camera.up = glm::vec3(0, 1, 0);
    s.camera.fovY = 20.0f;
    s.render.width = 32;
    s.render.height = 32;
    s.render.spp = 8;
    s.render.maxBounces = 8;
    s.render.rrDepth = 100;
    s.render.nee = false;   // BSDF sampling alone is exact here; light samples of the sky are not
    s.sky.type = Sky::Type::Constant;
    s.sky.color = glm::vec3(1.0f);
    Material grey;
    grey.name = "grey";
    grey.albedo = glm::vec3(0.5f);
    s.materials.push_back(grey);
    s.spheres.push_back(Sphere{});
    SelfTestResult r;
    r.name = "furnace";
    r.kind = "max deviation";
    r.alpha = 1e-5;   // float rounding of one scatter; a wrong weight is off by far more
    PathTracer tracer;
    tracer.setScene(s);
    renderProgressively(tracer, s.render);
    const Image image = tracer.readImage();
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c) {
                const double v = image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4 + std::size_t(c)];
                r.statistic = std::max(r.statistic, std::isfinite(v) ? std::abs(v - 0.5) : 1e30);
            }
    r.pass = r.statistic <= r.alpha;
    r.pValue = r.pass ? 1.0 : 0.0;
    if (!r.pass) r.detail = "pixels differ from 0.5: the Lambert weight or the sky is wrong";
    return r;
}

// The χ² verdict on binned samples: a pass needs p > alpha, no sample in a cell of pdf 0, no
// non-finite sample and no other failure (`otherFailure`, said as it is; empty for none).
SelfTestResult chiSquareVerdict(const std::string& name, const std::vector<double>& observed,
                                const std::vector<double>& expected, double alpha, int nonFinite,
                                const std::string& otherFailure) {
    const stats::ChiSquareResult chi = stats::chiSquareTest(observed, expected);
    SelfTestResult r;
    r.name = name;
    r.kind = "chi2";
    r.alpha = alpha;
    r.statistic = chi.statistic;
    r.dof = chi.dof;
    r.pValue = chi.pValue;
    r.pass = chi.pValue > alpha && !chi.sampleInZeroCell && nonFinite == 0 && otherFailure.empty();
    if (!otherFailure.empty()) r.detail = otherFailure;
    else if (chi.sampleInZeroCell) r.detail = "samples where the pdf is 0";
    else if (nonFinite > 0) r.detail = std::to_string(nonFinite) + " non-finite samples";
    else if (!r.pass) r.detail = "the samples do not follow the pdf";
    return r;
}

SelfTestResult chiSquare(const std::string& name, const std::vector<GpuSample>& samples, const LobeGrid& grid,
                         const std::function<double(glm::vec3)>& pdf, double alpha) {
    std::vector<double> observed(std::size_t(grid.na * grid.nphi), 0.0);
    int nonFinite = 0;
    for (const GpuSample& s : samples) {
        const glm::vec3 w = s.wi();
        if (!std::isfinite(w.x + w.y + w.z + s.pdf())) {
            ++nonFinite;
            continue;
        }
        if (s.lobe() == glsl::LOBE_NONE) continue;
        observed[std::size_t(grid.cell(w))] += 1.0;
    }
    const std::vector<double> expected = grid.expected(pdf, double(samples.size()), observed);
    return chiSquareVerdict(name, observed, expected, alpha, nonFinite, "");
}

// The sphere light's cone sampler seen from the origin: cells of equal solid angle over the cone
// (equal steps of 1 − cosθ around the axis by equal steps of φ), each expecting N × pdf × its
// solid angle, pdf the density the tracer divides by. A sample outside the cone (beyond float
// rounding) fails outright.
SelfTestResult sphereConeChiSquare(const GpuSampler& sampler, unsigned n, unsigned seed,
                                   const std::function<double(glm::vec3, float)>& pdf, double alpha) {
    const glm::vec3 axis = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
    const glm::vec3 center = 2.5f * axis;
    const float radius = 1.0f;
    const double omcMax = double(glsl::sphereConeOneMinusCos(glm::vec3(0.0f), center, radius));
    const glsl::Frame frame = glsl::frameFromNormal(axis);
    constexpr int nt = 16, nphi = 32;
    std::vector<double> observed(std::size_t(nt * nphi), 0.0);
    const double cellSolidAngle = omcMax / nt * (2.0 * M_PI / nphi);
    const std::vector<double> expected(observed.size(), double(n) * pdf(center, radius) * cellSolidAngle);
    int outside = 0, nonFinite = 0;
    for (const GpuSample& s : sampler.sphereCone(center, radius, n, seed)) {
        const glm::vec3 w = s.wi();
        if (!std::isfinite(w.x + w.y + w.z)) {
            ++nonFinite;
            continue;
        }
        const glm::vec3 l = glsl::frameToLocal(frame, w);
        const double omc = 1.0 - double(l.z);
        if (omc > omcMax * (1.0 + 1e-3) + 1e-6) {
            ++outside;
            continue;
        }
        double phi = std::atan2(double(l.y), double(l.x));
        if (phi < 0) phi += 2 * M_PI;
        observed[std::size_t(std::clamp(int(omc / omcMax * nt), 0, nt - 1) * nphi +
                             std::min(int(phi / (2 * M_PI) * nphi), nphi - 1))] += 1.0;
    }
    return chiSquareVerdict("sphere light cone", observed, expected, alpha, nonFinite,
                            outside > 0 ? std::to_string(outside) + " samples outside the cone" : "");
}

SelfTestResult failed(const std::string& name, const std::string& why) {
    SelfTestResult r;
    r.name = name;
    r.detail = why;
    return r;
}

} // namespace

bool SelfTestReport::pass() const {
    return !results.empty() && std::all_of(results.begin(), results.end(), [](const SelfTestResult& r) { return r.pass; });
}

SelfTestReport runSelfTest(const SelfTestOptions& o) {
    const auto start = std::chrono::steady_clock::now();
    SelfTestReport report;
    const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
    report.driver = std::string(renderer ? renderer : "?") + " / " + (version ? version : "?");
    try {
        report.results.push_back(furnace());
    } catch (const std::exception& e) {
        report.results.push_back(failed("furnace", e.what()));
    }
    const auto cosinePdf = o.cosinePdf ? o.cosinePdf : [](float c) { return double(glsl::pdfCosineHemisphere(c)); };
    const auto bsdfPdf = o.bsdfPdf ? o.bsdfPdf : [](const glsl::BsdfParams& m, glm::vec3 wo, glm::vec3 wi) {
        return double(glsl::bsdfPdf(m, wo, wi));
    };
    const auto conePdf = o.sphereConePdf ? o.sphereConePdf : [](glm::vec3 c, float r) {
        return double(glsl::sphereConePdf(glm::vec3(0.0f), c, r));
    };
    // GGX visible normals of a metal (F = 1, no diffuse lobe) at (α, cos θo).
    const float cases[][2] = {{0.1f, 0.9f}, {0.3f, 0.5f}, {0.6f, 0.2f}};
    // Cosine, the GGX cases, rough glass, the sphere cone.
    const int tests = 1 + int(std::size(cases)) + 2;
    const double alpha = stats::sidak(o.alpha, tests);
    try {
        const GpuSampler sampler;
        const LobeGrid hemisphere(glm::vec3(0, 0, 1), 1.0f);
        report.results.push_back(chiSquare("cosine hemisphere", sampler.cosineHemisphere(o.samples, o.seed), hemisphere,
                                           [&](glm::vec3 w) { return cosinePdf(w.z); }, alpha));
        unsigned seed = o.seed;
        for (const auto& c : cases) {
            const float a = c[0], mu = c[1];
            const glsl::BsdfParams m(glm::vec3(0.0f), glm::vec3(1.0f), a, 0.0f, 1.5f);
            const glm::vec3 wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
            const LobeGrid grid(glm::normalize(glm::vec3(-wo.x, -wo.y, wo.z)), std::max(2.0f * a, 0.02f));
            char name[64];
            std::snprintf(name, sizeof name, "GGX VNDF a=%.1f cos=%.1f", double(a), double(mu));
            report.results.push_back(chiSquare(name, sampler.bsdf(m, wo, o.samples, ++seed), grid,
                                               [&](glm::vec3 w) { return bsdfPdf(m, wo, w); }, alpha));
        }
        {
            // Rough glass (Walter et al. 2007), reflection and refraction together, from outside;
            // the cells centred on the refracted direction.
            const float a = 0.25f, mu = 0.7f;
            const glsl::BsdfParams m(glm::vec3(0.0f), glm::vec3(0.0f), a, 1.0f, 1.5f);
            const glm::vec3 wo(std::sqrt(1.0f - mu * mu), 0.0f, mu);
            const LobeGrid grid(glm::normalize(refractionLobeCentre(wo, 1.5f)), 2.0f * a);
            report.results.push_back(chiSquare("rough glass a=0.25 cos=0.7", sampler.bsdf(m, wo, o.samples, ++seed), grid,
                                               [&](glm::vec3 w) { return bsdfPdf(m, wo, w); }, alpha));
        }
        report.results.push_back(sphereConeChiSquare(sampler, o.samples, ++seed, conePdf, alpha));
    } catch (const std::exception& e) {
        report.results.push_back(failed("GLSL samplers", e.what()));
    }
    report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

std::string describe(const SelfTestResult& r) {
    char line[512];
    if (r.kind == "chi2")
        std::snprintf(line, sizeof line, "%s %s: chi2 %.1f, dof %d, p %.3g (alpha %.2g)%s%s", r.pass ? "PASS" : "FAIL",
                      r.name.c_str(), r.statistic, r.dof, r.pValue, r.alpha, r.detail.empty() ? "" : ": ", r.detail.c_str());
    else if (r.kind == "max deviation")
        std::snprintf(line, sizeof line, "%s %s: max deviation %.2g (tolerance %.2g)%s%s", r.pass ? "PASS" : "FAIL",
                      r.name.c_str(), r.statistic, r.alpha, r.detail.empty() ? "" : ": ", r.detail.c_str());
    else
        std::snprintf(line, sizeof line, "%s %s: %s", r.pass ? "PASS" : "FAIL", r.name.c_str(), r.detail.c_str());
    return line;
}

} // namespace raylab
