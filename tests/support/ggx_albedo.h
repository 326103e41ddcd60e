#pragma once
// Reference values for GGX tests, computed independently of the shader code.
#include <cmath>

namespace raylab::test {

// GGX single-scattering albedo with F = 1, E(μ, α) = ∫ D G2 / (4μ) dωi, by our own quadrature
// (double precision, independent of the shader code): substituting the D·cosθh measure
// dP = D(h) cosθh dωh, whose inverse CDF is tan²θh = α² u/(1 − u), and dωi = 4 (wo·h) dωh:
// E = ∫∫ G2(wo, wi(h)) (wo·h) / (μ cosθh) du dφ over the unit square, midpoint rule.
inline double ggxAlbedoQuadrature(double mu, double alpha, int k = 1500) {
    auto lambda = [alpha](double cz, double sz2) {
        const double x = alpha * alpha * sz2 / (cz * cz);
        return 0.5 * (std::sqrt(1.0 + x) - 1.0);
    };
    const double wx = std::sqrt(1.0 - mu * mu), wz = mu;
    double sum = 0.0;
    for (int i = 0; i < k; ++i) {
        const double u = (i + 0.5) / k;
        const double tan2 = alpha * alpha * u / (1.0 - u);
        const double ch = 1.0 / std::sqrt(1.0 + tan2), sh = std::sqrt(1.0 - ch * ch);
        for (int j = 0; j < k; ++j) {
            const double phi = (j + 0.5) / k * 2.0 * M_PI;
            const double hx = sh * std::cos(phi), hy = sh * std::sin(phi), hz = ch;
            const double oh = wx * hx + wz * hz;
            if (oh <= 0.0) continue;
            const double ix = 2 * oh * hx - wx, iy = 2 * oh * hy, iz = 2 * oh * hz - wz;
            if (iz <= 0.0) continue;
            const double g2 = 1.0 / (1.0 + lambda(wz, wx * wx) + lambda(iz, ix * ix + iy * iy));
            sum += g2 * oh / (mu * ch);
        }
    }
    return sum / (double(k) * k);
}


} // namespace raylab::test
