// Checks of the BRDF slots (Lambert, GGX D, Smith G1, Schlick F): pointwise against the reference
// on fixed directions, the white furnace and the normalisations that must hold exactly, reciprocity.
#include "exercise/check_support.h"

#include "shaders/include/ggx.glsl"

#include <cmath>
#include <numbers>
#include <random>

namespace raylab {
using namespace exercise;
namespace {

using glm::vec3;
using glm::vec4;
constexpr double kPi = std::numbers::pi;

// A direction above the surface at polar angle θ (radians) and azimuth φ.
vec3 polar(double theta, double phi) {
    return vec3(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)), float(std::cos(theta)));
}

vec3 randomAbove(std::mt19937& rng, float maxThetaDeg = 85.0f) {
    std::uniform_real_distribution<double> u(0.0, 1.0);
    return polar(glm::radians(double(maxThetaDeg)) * std::sqrt(u(rng)), 2.0 * kPi * u(rng));
}

// value / reference where the reference is not 0 (relative comparison), the value itself where it is.
std::vector<double> relative(const std::vector<double>& v, const std::vector<double>& ref) {
    std::vector<double> out(v.size());
    for (std::size_t i = 0; i < v.size(); ++i) out[i] = ref[i] != 0.0 ? v[i] / ref[i] : v[i];
    return out;
}

CheckResult verdict(const char* name, const char* exercise, const std::vector<double>& got, const std::vector<double>& want,
                    const std::vector<Mistake>& mistakes, double tolerance, const std::string& items) {
    const Comparison c = compare(got, want, tolerance);
    CheckResult res{name, c.wrong == 0, describe(c, items), "", ""};
    if (!res.pass) {
        const std::string why = diagnose(got, mistakes, tolerance);
        res.message = std::string(exercise) + ": " +
                      (why.empty() ? "differs from the reference, e.g. case " + std::to_string(c.firstWrong) + ": expected " +
                                         num(want[std::size_t(c.firstWrong)]) + ", got " + num(got[std::size_t(c.firstWrong)])
                                   : why);
    }
    return res;
}

// --- Lambert ------------------------------------------------------------------------------------

struct LambertCase {
    vec3 albedo, wo, wi;
};

std::vector<LambertCase> lambertCases() {
    std::mt19937 rng(19);
    std::vector<LambertCase> cases;
    const vec3 albedos[] = {vec3(1.0f), vec3(0.8f, 0.5f, 0.2f), vec3(0.05f, 0.3f, 0.9f)};
    for (const vec3& a : albedos)
        for (int i = 0; i < 20; ++i) cases.push_back({a, randomAbove(rng), randomAbove(rng)});
    return cases;
}

std::vector<vec3> lambertValues(const ExerciseProbe& probe, const std::vector<LambertCase>& cases) {
    std::vector<ProbeInput> in;
    for (const auto& c : cases) in.push_back({{vec4(c.albedo, 0.0f), vec4(c.wo, 0.0f), vec4(c.wi, 0.0f)}});
    std::vector<vec3> f;
    for (const auto& y : probe.run(ProbeMode::Lambert, in)) f.emplace_back(y.a);
    return f;
}

} // namespace

CheckResult checkLambertPointwise(const ExerciseProbe& probe) {
    const auto cases = lambertCases();
    const auto f = lambertValues(probe, cases);
    std::vector<double> got, want;
    Mistake noPi{"f misses the 1/π: ρ alone reflects π times the light it receives", {}};
    Mistake cosine{"f includes cos θi: return ρ/π alone, the renderer multiplies by cos θi itself", {}};
    Mistake twoPi{"f divides by 2π: ∫ cos θ dω over the hemisphere is π, so f = ρ/π", {}};
    for (std::size_t i = 0; i < cases.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const double rho = cases[i].albedo[k];
            got.push_back(f[i][k]);
            want.push_back(rho / kPi);
            noPi.values.push_back(rho);
            cosine.values.push_back(rho / kPi * cases[i].wi.z);
            twoPi.values.push_back(rho / (2.0 * kPi));
        }
    return verdict("lambert-pointwise", "Lambert", got, want, {noPi, cosine, twoPi}, 1e-5, "values");
}

CheckResult checkLambertFurnace(const ExerciseProbe& probe) {
    // ∫ f cos θi dωi by the midpoint rule on θ × φ, for white ρ = 1 and three views.
    const int nt = 64, np = 32;
    const vec3 views[] = {polar(0.0, 0.0), polar(1.0, 0.5), polar(1.45, 2.0)};
    std::vector<LambertCase> cases;
    for (const vec3& wo : views)
        for (int i = 0; i < nt; ++i)
            for (int j = 0; j < np; ++j)
                cases.push_back({vec3(1.0f), wo, polar((i + 0.5) * kPi / 2.0 / nt, (j + 0.5) * 2.0 * kPi / np)});
    const auto f = lambertValues(probe, cases);
    double worst = 0.0, worstE = 1.0;
    for (int v = 0; v < 3; ++v) {
        double e = 0.0;
        for (int k = 0; k < nt * np; ++k) {
            const auto& c = cases[std::size_t(v * nt * np + k)];
            const double sinT = std::sqrt(std::max(0.0, 1.0 - double(c.wi.z) * c.wi.z));
            e += double(f[std::size_t(v * nt * np + k)].x) * c.wi.z * sinT * (kPi / 2.0 / nt) * (2.0 * kPi / np);
        }
        if (std::isnan(e) || std::abs(e - 1.0) >= std::abs(worstE - 1.0)) {
            worst = std::abs(e - 1.0);
            worstE = e;
        }
    }
    CheckResult res{"furnace", std::abs(worstE - 1.0) < 1e-3,
                    "white furnace: reflected energy " + num(worstE) + " (must be 1, error " + num(worst) + ")", "", ""};
    if (res.pass) return res;
    if (std::abs(worstE - kPi) < 1e-2)
        res.message = "Lambert: energy π: f misses the 1/π";
    else if (std::abs(worstE - 2.0 / 3.0) < 1e-2)
        res.message = "Lambert: energy 2/3: f includes cos θi, which the renderer multiplies by again";
    else if (std::abs(worstE - 0.5) < 1e-2)
        res.message = "Lambert: energy 1/2: f divides by 2π instead of π";
    else
        res.message = worstE > 1.0 ? "Lambert: a white surface reflects more light than it receives"
                                   : "Lambert: a white surface loses light";
    return res;
}

CheckResult checkLambertReciprocity(const ExerciseProbe& probe) {
    auto cases = lambertCases();
    const std::size_t n = cases.size();
    for (std::size_t i = 0; i < n; ++i) cases.push_back({cases[i].albedo, cases[i].wi, cases[i].wo});
    const auto f = lambertValues(probe, cases);
    std::vector<double> got, want;
    for (std::size_t i = 0; i < n; ++i)
        for (int k = 0; k < 3; ++k) {
            got.push_back(f[i + n][k]);
            want.push_back(f[i][k]);
        }
    CheckResult res = verdict("reciprocity", "Lambert", got, want, {}, 1e-5, "swapped pairs");
    if (!res.pass) res.message = "Lambert: f(wo, wi) ≠ f(wi, wo): a BRDF is the same both ways (Helmholtz reciprocity)";
    return res;
}

// --- GGX D --------------------------------------------------------------------------------------
namespace {

struct DCase {
    vec3 h;
    float alpha;
};

std::vector<double> dValues(const ExerciseProbe& probe, const std::vector<DCase>& cases) {
    std::vector<ProbeInput> in;
    for (const auto& c : cases) in.push_back({{vec4(c.h, c.alpha)}});
    std::vector<double> out;
    for (const auto& y : probe.run(ProbeMode::GgxD, in)) out.push_back(y.a.x);
    return out;
}

} // namespace

CheckResult checkGgxDPointwise(const ExerciseProbe& probe) {
    std::mt19937 rng(20);
    std::vector<DCase> cases;
    for (float alpha : {0.1f, 0.3f, 0.6f, 1.0f}) {
        for (int i = 0; i < 20; ++i) cases.push_back({randomAbove(rng, std::min(85.0f, 200.0f * alpha)), alpha});
        cases.push_back({vec3(0.0f, 0.0f, 1.0f), alpha});
        cases.push_back({glm::normalize(vec3(1.0f, 0.0f, -0.2f)), alpha});   // below the horizon
    }
    const auto got = dValues(probe, cases);
    std::vector<double> want;
    Mistake noPi{"D misses the π in the denominator", {}};
    Mistake alphaForA2{"D uses α where α² belongs", {}};
    Mistake alpha4{"D squares α twice: α⁴ where α² belongs", {}};
    Mistake cos2{"D has cos²θ where cos⁴θ belongs", {}};
    for (const auto& c : cases) {
        // The reference leaves normals below the horizon to its callers; the exercise asks for 0.
        const double d = c.h.z > 0.0f ? glsl::ggxD(c.h, c.alpha) : 0.0;
        want.push_back(d);
        noPi.values.push_back(d * kPi);
        alphaForA2.values.push_back(c.h.z > 0.0f ? glsl::ggxD(c.h, std::sqrt(c.alpha)) : 0.0);
        alpha4.values.push_back(c.h.z > 0.0f ? glsl::ggxD(c.h, c.alpha * c.alpha) : 0.0);
        cos2.values.push_back(d * c.h.z * c.h.z);
    }
    for (auto* m : {&noPi, &alphaForA2, &alpha4, &cos2}) m->values = relative(m->values, want);
    return verdict("ggx-d-pointwise", "GGX D", relative(got, want), relative(want, want), {noPi, alphaForA2, alpha4, cos2}, 1e-3,
                   "values");
}

CheckResult checkGgxDNormalisation(const ExerciseProbe& probe) {
    const int nt = 4000;
    const float alphas[] = {0.1f, 0.3f, 0.7f};
    std::vector<DCase> cases;
    for (float a : alphas)
        for (int i = 0; i < nt; ++i) cases.push_back({polar((i + 0.5) * kPi / 2.0 / nt, 0.3), a});
    const auto d = dValues(probe, cases);
    double worstE = 1.0;
    std::string each;
    for (int k = 0; k < 3; ++k) {
        double e = 0.0;
        for (int i = 0; i < nt; ++i) {
            const double theta = (i + 0.5) * kPi / 2.0 / nt;
            e += d[std::size_t(k * nt + i)] * std::cos(theta) * std::sin(theta) * (kPi / 2.0 / nt) * 2.0 * kPi;
        }
        each += (each.empty() ? "" : ", ") + ("α " + num(alphas[k]) + ": " + num(e));
        if (std::isnan(e) || std::abs(e - 1.0) > std::abs(worstE - 1.0)) worstE = e;
    }
    CheckResult res{"ggx-d-normalisation", std::abs(worstE - 1.0) < 2e-3, "∫ D cos θ dω = " + each + " (must be 1)", "", ""};
    if (res.pass) return res;
    res.message = std::abs(worstE - kPi) < 2e-2 ? "GGX D: the projected area is π, not 1: D misses the π in the denominator"
                                                : "GGX D: the microfacets' projected area ∫ D cos θ dω is not 1";
    return res;
}

// --- Smith G1 -----------------------------------------------------------------------------------
namespace {

std::vector<double> g1Values(const ExerciseProbe& probe, const std::vector<DCase>& cases) {
    std::vector<ProbeInput> in;
    for (const auto& c : cases) in.push_back({{vec4(c.h, c.alpha), vec4(0.0f, 0.0f, 1.0f, 0.0f)}});
    std::vector<double> out;
    for (const auto& y : probe.run(ProbeMode::SmithG, in)) out.push_back(y.a.x);
    return out;
}

double g1Exact(vec3 w, double alpha, double alphaPower, double tanPower) {
    if (w.z <= 0.0f) return 0.0;
    const double c2 = double(w.z) * w.z, tan2 = (1.0 - c2) / c2;
    return 2.0 / (1.0 + std::sqrt(1.0 + std::pow(alpha, alphaPower) * std::pow(tan2, tanPower / 2.0)));
}

} // namespace

CheckResult checkSmithGPointwise(const ExerciseProbe& probe) {
    std::mt19937 rng(21);
    std::vector<DCase> cases;
    for (float alpha : {0.1f, 0.3f, 0.6f, 1.0f}) {
        for (int i = 0; i < 20; ++i) cases.push_back({randomAbove(rng, 89.0f), alpha});
        cases.push_back({vec3(0.0f, 0.0f, 1.0f), alpha});
    }
    const auto got = g1Values(probe, cases);
    std::vector<double> want;
    Mistake schlick{"G1 is the Schlick–Smith approximation cos θ / (cos θ (1 − k) + k), not GGX's exact G1", {}};
    Mistake alpha1{"G1 uses α tan²θ where α² tan²θ belongs", {}};
    Mistake alpha4{"G1 squares α twice: α⁴ tan²θ where α² tan²θ belongs", {}};
    Mistake tan1{"G1 uses tan θ where tan²θ belongs", {}};
    for (const auto& c : cases) {
        want.push_back(g1Exact(c.h, c.alpha, 2.0, 2.0));
        const double k = c.alpha / 2.0, cz = c.h.z;
        schlick.values.push_back(cz / (cz * (1.0 - k) + k));
        alpha1.values.push_back(g1Exact(c.h, c.alpha, 1.0, 2.0));
        alpha4.values.push_back(g1Exact(c.h, c.alpha, 4.0, 2.0));
        tan1.values.push_back(g1Exact(c.h, c.alpha, 2.0, 1.0));
    }
    return verdict("smith-g-pointwise", "Smith G", got, want, {schlick, alpha1, alpha4, tan1}, 1e-4, "values");
}

CheckResult checkSmithGVisibleNormals(const ExerciseProbe& probe) {
    // G1(wo) ∫ max(0, wo·h) D(h) dωh = cos θo (Heitz 2014, eq. 14: the visible projected area),
    // with the reference D, integrated by the midpoint rule on θ × φ.
    const int nt = 600, np = 300;
    std::vector<DCase> views;
    for (float alpha : {0.3f, 0.8f})
        for (double thetaDeg : {0.0, 30.0, 60.0, 80.0}) views.push_back({polar(glm::radians(thetaDeg), 0.0), alpha});
    const auto g1 = g1Values(probe, views);
    double worst = 0.0;
    std::string each;
    for (std::size_t v = 0; v < views.size(); ++v) {
        const vec3 wo = views[v].h;
        double area = 0.0;
        for (int i = 0; i < nt; ++i)
            for (int j = 0; j < np; ++j) {
                const double theta = (i + 0.5) * kPi / 2.0 / nt, phi = (j + 0.5) * 2.0 * kPi / np;
                const vec3 h = polar(theta, phi);
                area += std::max(0.0, double(glm::dot(wo, h))) * glsl::ggxD(h, views[v].alpha) * std::sin(theta) *
                        (kPi / 2.0 / nt) * (2.0 * kPi / np);
            }
        const double ratio = g1[v] * area / wo.z;
        if (std::isnan(ratio) || std::abs(ratio - 1.0) > worst) worst = std::isnan(ratio) ? 1e30 : std::abs(ratio - 1.0);
        if (v % 4 == 2) each += (each.empty() ? "" : ", ") + ("α " + num(views[v].alpha) + " θo 60°: " + num(ratio));
    }
    CheckResult res{"smith-g-visible-normals", worst < 5e-3,
                    "G1 · visible projected area / cos θo: " + each + "; worst |ratio − 1| " + num(worst), "", ""};
    if (!res.pass)
        res.message = "Smith G: the visible microfacets' projected area G1(wo) ∫ max(0, wo·h) D dω must equal cos θo";
    return res;
}

// --- Schlick ------------------------------------------------------------------------------------

CheckResult checkSchlickPointwise(const ExerciseProbe& probe) {
    std::mt19937 rng(22);
    struct Case {
        vec3 f0;
        float f90;
        vec3 wo, wi;
    };
    std::vector<Case> cases;
    for (const vec3& f0 : {vec3(0.04f), vec3(0.95f, 0.64f, 0.54f)})
        for (float f90 : {1.0f, 0.6f})
            for (int i = 0; i < 15; ++i) cases.push_back({f0, f90, randomAbove(rng, 88.0f), randomAbove(rng, 88.0f)});
    std::vector<ProbeInput> in;
    for (const auto& c : cases) in.push_back({{vec4(c.f0, c.f90), vec4(c.wo, 0.0f), vec4(c.wi, 0.0f)}});
    const auto out = probe.run(ProbeMode::Schlick, in);
    std::vector<double> got, want;
    Mistake woN{"F(θ) matches with ωo·n in place of ωo·h: the microfacet's normal is h = normalize(ωo + ωi)", {}};
    Mistake wiN{"F(θ) matches with ωi·n in place of ωi·h: the microfacet's normal is h = normalize(ωo + ωi)", {}};
    Mistake wiWo{"F(θ) matches with ωi·ωo in place of ωi·h: cos θ is taken against the halfway vector h", {}};
    Mistake pow4{"(1 − cos θ) is raised to the power 4, not 5", {}};
    Mistake noF90{"F ignores f90: it is f0 + (f90 − f0)(1 − cos θ)⁵, with f90 in place of 1", {}};
    Mistake cosPow{"F uses cos⁵θ where (1 − cos θ)⁵ belongs", {}};
    auto schlick = [](double f0, double f90, double c, double power) {
        return f0 + (f90 - f0) * std::pow(1.0 - std::clamp(c, 0.0, 1.0), power);
    };
    for (std::size_t i = 0; i < cases.size(); ++i) {
        const auto& c = cases[i];
        const glm::dvec3 wo(c.wo), wi(c.wi), h = glm::normalize(wo + wi);
        const double cosH = glm::dot(wi, h);
        for (int k = 0; k < 3; ++k) {
            const double f0 = c.f0[k], f90 = c.f90;
            got.push_back(out[i].a[k]);
            want.push_back(schlick(f0, f90, cosH, 5.0));
            woN.values.push_back(schlick(f0, f90, wo.z, 5.0));
            wiN.values.push_back(schlick(f0, f90, wi.z, 5.0));
            wiWo.values.push_back(schlick(f0, f90, glm::dot(wi, wo), 5.0));
            pow4.values.push_back(schlick(f0, f90, cosH, 4.0));
            noF90.values.push_back(schlick(f0, 1.0, cosH, 5.0));
            cosPow.values.push_back(f0 + (f90 - f0) * std::pow(std::clamp(cosH, 0.0, 1.0), 5.0));
        }
    }
    return verdict("schlick-pointwise", "Schlick", got, want, {woN, wiN, wiWo, pow4, noF90, cosPow}, 1e-4, "values");
}

} // namespace raylab
