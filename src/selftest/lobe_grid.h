#pragma once
// Histogram cells for χ² tests of direction samplers, adapted to lobes of any width, with
// expected counts by numerical integration of a pdf (the tests and the viewer's self-test).
#include "shaders/include/frame.glsl"

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace raylab {

// Centre of a smooth-glass lobe for wo and the relative index eta (the far side over wo's side):
// the direction refracted by Snell's law, or the mirror direction under total internal reflection.
inline glm::vec3 refractionLobeCentre(glm::vec3 wo, float eta) {
    const float side = wo.z > 0.0f ? 1.0f : -1.0f, mu = std::abs(wo.z);
    const float sin2T = (1.0f - mu * mu) / (eta * eta);
    if (sin2T >= 1.0f) return glm::vec3(-wo.x, -wo.y, wo.z);
    return -wo / eta + glm::vec3(0.0f, 0.0f, side * (mu / eta - std::sqrt(1.0f - sin2T)));
}

// Cells over the whole sphere of directions in coordinates around a centre direction r:
// a = g / (c + g) with g = tan(θ'/2), θ' the angle from r, and φ' around r. Half of the a range
// covers θ' < 2 atan(c), so a lobe of width ~c is resolved however narrow it is.
struct LobeGrid {
    glm::vec3 r;
    float c;
    int na = 16, nphi = 32;
    glsl::Frame frame;
    LobeGrid(glm::vec3 centre, float width) : r(centre), c(width), frame(glsl::frameFromNormal(centre)) {}

    int cell(glm::vec3 w) const {
        // In double, and θ' by atan2: acos of a float dot product cannot resolve the tiny angles
        // of narrow lobes (1 − θ²/2 rounds to float's 6e-8 steps).
        const glm::dvec3 d = glm::normalize(glm::dvec3(w));
        const double x = glm::dot(d, glm::dvec3(frame.t)), y = glm::dot(d, glm::dvec3(frame.b));
        const double z = glm::dot(d, glm::dvec3(r));
        const double theta = std::atan2(std::sqrt(x * x + y * y), z);
        const double g = std::tan(theta / 2.0);
        const double a = std::isinf(g) ? 1.0 : g / (c + g);
        double phi = std::atan2(y, x);
        if (phi < 0) phi += 2 * M_PI;
        const int ia = std::min(int(a * na), na - 1), ip = std::min(int(phi / (2 * M_PI) * nphi), nphi - 1);
        return ia * nphi + ip;
    }
    // Direction and Jacobian |dω / (da dφ)| at (a, φ).
    glm::vec3 direction(double a, double phi, double& jacobian) const {
        const double g = c * a / (1.0 - a);
        const double theta = 2.0 * std::atan(g);
        jacobian = std::sin(theta) * 2.0 / (1.0 + g * g) * c / ((1.0 - a) * (1.0 - a));
        const double st = std::sin(theta);
        return glsl::frameToWorld(frame, glm::vec3(float(st * std::cos(phi)), float(st * std::sin(phi)), float(std::cos(theta))));
    }
    // N × ∫cell pdf over cell (ia, ip) by the midpoint rule on k × k sub-cells.
    double integrateCell(const std::function<double(glm::vec3)>& pdf, double n, int ia, int ip, int k) const {
        double sum = 0.0;
        for (int i = 0; i < k; ++i)
            for (int j = 0; j < k; ++j) {
                const double a = (ia + (i + 0.5) / k) / na;
                const double phi = (ip + (j + 0.5) / k) / nphi * 2 * M_PI;
                double jac = 0.0;
                sum += pdf(direction(a, phi, jac)) * jac;
            }
        return n * sum / (double(k) * k) * (1.0 / na) * (2 * M_PI / nphi);
    }

    // N × ∫cell pdf by the midpoint rule on k × k sub-cells, k doubled from 16 until the count
    // changes by less than a tenth of its Poisson standard deviation (k ≤ 256); cells that
    // straddle the horizon (where the pdf jumps to 0; found from the sign of z over the cell's
    // sub-cell corners) start at 128 and may reach 512.
    std::vector<double> expected(const std::function<double(glm::vec3)>& pdf, double n) const {
        std::vector<double> e(size_t(na * nphi), 0.0);
        for (int ia = 0; ia < na; ++ia)
            for (int ip = 0; ip < nphi; ++ip) {
                bool below = false, above = false;
                for (int i = 0; i <= 16; ++i)
                    for (int j = 0; j <= 16; ++j) {
                        double jac = 0.0;
                        const double a = std::min((ia + i / 16.0) / na, 1.0 - 1e-9);
                        const glm::vec3 w = direction(a, (ip + j / 16.0) / nphi * 2 * M_PI, jac);
                        (w.z > 0.0f ? above : below) = true;
                    }
                const bool horizon = below && above;
                int k = horizon ? 128 : 16;
                const int kMax = horizon ? 512 : 256;
                double v = integrateCell(pdf, n, ia, ip, k);
                while (k < kMax) {
                    k *= 2;
                    const double finer = integrateCell(pdf, n, ia, ip, k);
                    const bool converged = std::abs(finer - v) < 0.1 * std::sqrt(std::max(finer, 1.0));
                    v = finer;
                    if (converged) break;
                }
                e[size_t(ia * nphi + ip)] = v;
            }
        return e;
    }

    // The same, then cells that received samples but integrated to 0 are integrated again on a
    // 2048 × 2048 grid: a pdf that is non-zero on a sliver thinner than the sub-cells (beyond a
    // critical angle, say) must not turn into a false "sample where the pdf is 0".
    std::vector<double> expected(const std::function<double(glm::vec3)>& pdf, double n,
                                 const std::vector<double>& observed) const {
        std::vector<double> e = expected(pdf, n);
        for (size_t i = 0; i < e.size(); ++i)
            if (e[i] == 0.0 && observed[i] > 0.0)
                e[i] = integrateCell(pdf, n, int(i) / nphi, int(i) % nphi, 2048);
        return e;
    }
};

} // namespace raylab
