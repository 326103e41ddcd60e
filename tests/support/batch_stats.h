#pragma once
// Per-pixel agreement of two renderers of the same scene: each rendered in independent batches
// (seeds), compared pixel by pixel with a z-test on the batch means. Needs a current GL context.
#include "render/path_tracer.h"
#include "render/progressive_render.h"
#include "scene/scene.h"
#include "support/statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace raylab::test {

// Per-pixel, per-channel mean and variance of the mean over independent batches (seeds).
struct BatchStats {
    std::vector<double> mean, varianceOfMean;
};

inline BatchStats renderBatches(Scene scene, int batches, TracerOptions options = {}) {
    PathTracer tracer(options);
    std::vector<double> sum, sum2;
    for (int b = 0; b < batches; ++b) {
        scene.render.seed = 1000u + std::uint32_t(b) * 7919u;
        tracer.setScene(scene);
        renderProgressively(tracer, scene.render);
        const Image img = tracer.readImage();
        if (sum.empty()) {
            sum.assign(img.rgba.size(), 0.0);
            sum2.assign(img.rgba.size(), 0.0);
        }
        for (size_t i = 0; i < img.rgba.size(); ++i) {
            sum[i] += img.rgba[i];
            sum2[i] += double(img.rgba[i]) * img.rgba[i];
        }
    }
    BatchStats s;
    for (size_t i = 0; i < sum.size(); ++i) {
        const double m = sum[i] / batches;
        const double var = std::max(0.0, (sum2[i] - batches * m * m) / (batches - 1));
        s.mean.push_back(m);
        s.varianceOfMean.push_back(var / batches);
    }
    return s;
}

// Two-sided normal quantile: z with P(|Z| > z) = p, by bisection on erfc.
inline double normalQuantileTwoSided(double p) {
    double lo = 0.0, hi = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (std::erfc(mid / std::sqrt(2.0)) > p ? lo : hi) = mid;
    }
    return 0.5 * (lo + hi);
}

// Fraction of pixels whose means agree: per-channel z-test at α = 0.01, Šidák-corrected over
// every pixel and channel (as Mitsuba's render tests do).
inline double fractionAgreeing(const BatchStats& a, const BatchStats& b) {
    const size_t pixels = a.mean.size() / 4;
    const double z = normalQuantileTwoSided(sidak(0.01, int(pixels * 3)));
    size_t agree = 0;
    for (size_t p = 0; p < pixels; ++p) {
        bool ok = true;
        for (size_t c = 0; c < 3; ++c) {
            const size_t i = p * 4 + c;
            const double d = std::abs(a.mean[i] - b.mean[i]);
            const double sd = std::sqrt(a.varianceOfMean[i] + b.varianceOfMean[i]);
            if (sd == 0.0 ? d > 1e-6 * std::max(1.0, std::abs(a.mean[i])) : d > z * sd) {
                ok = false;
                if (std::getenv("RAYLAB_DEBUG_Z"))
                    std::printf("pixel %zu (%zu,%zu) c%zu: %g vs %g, sd %g %g\n", p, p % 24, p / 24, c, a.mean[i], b.mean[i],
                                std::sqrt(a.varianceOfMean[i]), std::sqrt(b.varianceOfMean[i]));
            }
        }
        agree += ok ? 1 : 0;
    }
    return double(agree) / double(pixels);
}

// Fraction of block × block pixel squares whose mean agrees between the two, per channel, by a
// z-test at α = 0.01 (Šidák over blocks and channels). Pixels are independent (their own random
// streams), so a block mean's variance is the sum of its pixels' over the block size squared.
// For estimators with rare, bright samples (BSDF sampling of a small light), whose per-pixel batch
// means are far from normal, the block means are much closer to normal.
inline double fractionOfBlocksAgreeing(const BatchStats& a, const BatchStats& b, int width, int block) {
    const int height = int(a.mean.size() / 4) / width;
    const int bw = width / block, bh = height / block;
    const double z = normalQuantileTwoSided(sidak(0.01, bw * bh * 3));
    int agree = 0;
    for (int by = 0; by < bh; ++by)
        for (int bx = 0; bx < bw; ++bx) {
            bool ok = true;
            for (size_t c = 0; c < 3; ++c) {
                double ma = 0, mb = 0, va = 0, vb = 0;
                for (int y = by * block; y < (by + 1) * block; ++y)
                    for (int x = bx * block; x < (bx + 1) * block; ++x) {
                        const size_t i = size_t(y * width + x) * 4 + c;
                        ma += a.mean[i];
                        mb += b.mean[i];
                        va += a.varianceOfMean[i];
                        vb += b.varianceOfMean[i];
                    }
                const double n = double(block * block);
                const double d = std::abs(ma - mb) / n, sd = std::sqrt(va + vb) / n;
                if (d > z * sd) ok = false;
            }
            agree += ok ? 1 : 0;
        }
    return double(agree) / double(bw * bh);
}

} // namespace raylab::test
