// Checks of the thin-lens slot: every ray of a pixel meets the pinhole ray's point on the focus
// plane, the origins are uniform on the lens disk, and radius 0 is the pinhole camera.
#include "exercise/check_support.h"

#include "shaders/include/camera.glsl"

#include <cmath>
#include <random>

namespace raylab {
using namespace exercise;
namespace {

using glm::vec2;
using glm::vec3;
using glm::vec4;

constexpr float kRadius = 0.2f;
constexpr float kFocus = 4.0f;

glsl::CameraBasis testCamera() {
    return glsl::cameraBasis(vec3(1.0f, 2.0f, 3.0f), vec3(0.0f, 1.0f, -5.0f), vec3(0.0f, 1.0f, 0.0f), 50.0f, 1.5f);
}

struct LensRay {
    vec2 ndc, lens;
    float radius;
    vec3 origin, dir;
};

std::vector<LensRay> lensRays(const ExerciseProbe& probe, const std::vector<vec2>& ndcs, int perPixel, float radius) {
    const glsl::CameraBasis cam = testCamera();
    std::mt19937 rng(23);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    std::vector<LensRay> rays;
    std::vector<ProbeInput> in;
    for (const vec2& ndc : ndcs)
        for (int k = 0; k < perPixel; ++k) {
            const vec2 lens(u(rng), u(rng));
            rays.push_back({ndc, lens, radius, vec3(0.0f), vec3(0.0f)});
            in.push_back({{vec4(cam.origin, cam.tanHalfFovY), vec4(cam.right, cam.aspect), vec4(cam.up, radius),
                           vec4(cam.forward, kFocus), vec4(ndc, lens)}});
        }
    const auto out = probe.run(ProbeMode::ThinLens, in);
    for (std::size_t i = 0; i < rays.size(); ++i) {
        rays[i].origin = vec3(out[i].a);
        rays[i].dir = vec3(out[i].b);
    }
    return rays;
}

// The pinhole ray's (unnormalised) direction: its component along forward is 1.
glm::dvec3 pinholeDir(const glsl::CameraBasis& cam, vec2 ndc) {
    return glm::dvec3(cam.forward) + double(ndc.x * cam.tanHalfFovY * cam.aspect) * glm::dvec3(cam.right) +
           double(ndc.y * cam.tanHalfFovY) * glm::dvec3(cam.up);
}

// Distance from point p to the line through o along unit d.
double lineDistance(glm::dvec3 p, glm::dvec3 o, glm::dvec3 d) {
    const glm::dvec3 v = p - o;
    return glm::length(v - glm::dot(v, d) * d);
}

} // namespace

CheckResult checkLensFocus(const ExerciseProbe& probe) {
    const glsl::CameraBasis cam = testCamera();
    const std::vector<vec2> ndcs = {vec2(0.0f), vec2(-1.0f, -1.0f), vec2(1.0f, 1.0f), vec2(0.7f, -0.3f), vec2(-0.4f, 0.9f)};
    const auto rays = lensRays(probe, ndcs, 64, kRadius);
    const auto pinholes = lensRays(probe, ndcs, 1, 0.0f);
    int notUnit = 0, offFocus = 0, onSphere = 0, pinholeWrong = 0;
    double worst = 0.0;
    for (const LensRay& r : rays) {
        const glm::dvec3 o(r.origin), d(r.dir);
        if (!(std::abs(glm::length(d) - 1.0) < 1e-4)) ++notUnit;
        const glm::dvec3 dn = glm::length(d) > 0.0 ? d / glm::length(d) : d;
        const glm::dvec3 pd = pinholeDir(cam, r.ndc);
        const double miss = lineDistance(glm::dvec3(cam.origin) + double(kFocus) * pd, o, dn);
        worst = std::isnan(miss) ? 1e30 : std::max(worst, miss);
        if (!(miss < 1e-4 * kFocus)) ++offFocus;
        if (lineDistance(glm::dvec3(cam.origin) + double(kFocus) * glm::normalize(pd), o, dn) < 1e-4 * kFocus) ++onSphere;
    }
    for (const LensRay& r : pinholes) {
        const glm::dvec3 want = glm::normalize(pinholeDir(cam, r.ndc));
        if (!(glm::length(glm::dvec3(r.origin) - glm::dvec3(cam.origin)) < 1e-5 && glm::length(glm::dvec3(r.dir) - want) < 1e-4))
            ++pinholeWrong;
    }
    const int n = int(rays.size());
    CheckResult res{"lens-focus", notUnit == 0 && offFocus == 0 && pinholeWrong == 0,
                    std::to_string(offFocus) + " of " + std::to_string(n) + " rays miss their focus point (worst by " + num(worst) +
                        "), " + std::to_string(notUnit) + " directions not unit, " + std::to_string(pinholeWrong) + " of " +
                        std::to_string(pinholes.size()) + " radius-0 rays differ from the pinhole ray",
                    "", ""};
    if (res.pass) return res;
    if (offFocus > 0 && onSphere == n)
        res.message = "thin lens: the sharp points lie focusDistance along the normalised direction (a sphere), not on the "
                      "plane focusDistance ahead: aim at cam.origin + focusDistance·d with d unnormalised (its forward part is 1)";
    else if (offFocus > 0)
        res.message = "thin lens: the rays of a pixel do not meet on the focus plane: aim each ray from its lens point at "
                      "cam.origin + focusDistance·d";
    else if (notUnit > 0)
        res.message = "thin lens: the direction must be a unit vector: normalize(focus − origin)";
    else
        res.message = "thin lens: with lensRadius 0 the ray must be the pinhole ray";
    return res;
}

CheckResult checkLensDisk(const ExerciseProbe& probe) {
    const glsl::CameraBasis cam = testCamera();
    const int n = 4096;
    const auto rays = lensRays(probe, {vec2(0.3f, 0.2f)}, n, kRadius);
    int offPlane = 0;
    double maxR = 0.0, meanR2 = 0.0, meanX = 0.0, meanY = 0.0;
    for (const LensRay& r : rays) {
        const glm::dvec3 q = glm::dvec3(r.origin) - glm::dvec3(cam.origin);
        if (!(std::abs(glm::dot(q, glm::dvec3(cam.forward))) < 1e-5)) ++offPlane;
        const double x = glm::dot(q, glm::dvec3(cam.right)) / kRadius, y = glm::dot(q, glm::dvec3(cam.up)) / kRadius;
        maxR = std::max(maxR, std::sqrt(x * x + y * y));
        meanR2 += (x * x + y * y) / n;
        meanX += x / n;
        meanY += y / n;
    }
    // Uniform on the unit disk: r² is uniform on [0, 1] (mean 1/2, variance 1/12), x and y have mean
    // 0 and variance 1/4; 5σ bounds keep a correct lens from failing by chance (p < 1e-6).
    const double sigmaR2 = std::sqrt(1.0 / 12.0 / n), sigmaXY = std::sqrt(0.25 / n);
    const bool uniform = std::abs(meanR2 - 0.5) < 5.0 * sigmaR2 && std::abs(meanX) < 5.0 * sigmaXY && std::abs(meanY) < 5.0 * sigmaXY;
    CheckResult res{"lens-disk", offPlane == 0 && maxR <= 1.0 + 1e-4 && maxR > 0.95 && uniform,
                    "lens points / lensRadius: max radius " + num(maxR) + ", mean r² " + num(meanR2) + " (uniform: 1/2), mean (" +
                        num(meanX) + ", " + num(meanY) + "), " + std::to_string(offPlane) + " of " + std::to_string(n) +
                        " off the lens plane",
                    "", ""};
    if (res.pass) return res;
    if (offPlane > 0)
        res.message = "thin lens: ray origins leave the lens plane: move the origin along cam.right and cam.up only";
    else if (maxR < 1e-6)
        res.message = "thin lens: every ray starts at the lens centre: no depth of field";
    else if (std::abs(maxR - 2.0) < 0.1)
        res.message = "thin lens: lens points reach 2·lensRadius: lensRadius is the radius, not the diameter";
    else if (std::abs(maxR - 0.5) < 0.05)
        res.message = "thin lens: lens points reach only lensRadius/2: lensRadius is the radius, not the diameter";
    else if (maxR > 1.0 + 1e-4)
        res.message = "thin lens: lens points fall outside the disk of radius lensRadius (a square lens?)";
    else if (std::abs(meanR2 - 1.0 / 3.0) < 5.0 * sigmaR2)
        res.message = "thin lens: lens points crowd the disk's centre: a uniform disk needs radius √u, not u";
    else
        res.message = "thin lens: lens points are not uniform on the disk";
    return res;
}

} // namespace raylab
