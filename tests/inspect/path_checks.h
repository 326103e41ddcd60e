#pragma once
// The path inspector's invariants, checked on every recorded path of every test scene: the terms
// that count multiply out to the sample's value, and the throughput chains from bounce to bounce
// (before × f·|cosθ|/pdf ÷ q = after = the next bounce's before).
#include "inspect/path_record.h"

#include <glm/glm.hpp>
#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace raylab::test {

// What the checks saw, so that callers can show they were not vacuous.
struct PathCheckCounts {
    int paths = 0;
    int chained = 0;            // bounces whose throughput after was checked against before × weight / q
    int weightsChecked = 0;     // non-delta samples whose weight was checked against f·|cosθ|/pdf
    int deltaSamples = 0;
    int roulette = 0;           // bounces where Russian roulette was played
    int stageAlbedo = 0;        // bounces with render.stage primary's albedo term
    int lobes[5] = {0, 0, 0, 0, 0};   // samples per lobe (LOBE_*)
    int notCounted = 0;         // non-zero terms a bounce view left out of the value
};

inline void expectNearRelative(glm::vec3 actual, glm::vec3 expected, float relative, const std::string& what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(actual[c], expected[c], relative * (std::abs(expected[c]) + std::abs(actual[c])) + 1e-30f)
            << what << " channel " << c;
}

inline PathCheckCounts expectTermsMultiplyOut(const std::vector<PathRecord>& paths, const std::string& where) {
    PathCheckCounts n;
    for (const PathRecord& p : paths) {
        ++n.paths;
        EXPECT_FALSE(p.truncated) << where;
        if (p.truncated) continue;
        const std::string path = where + " sample " + std::to_string(p.sample);
        // The value: relative to the sum of the terms' magnitudes (float rounding of a sum is
        // bounded by that).
        const glm::dvec3 sum = p.sumOfTerms();
        glm::dvec3 magnitude(0.0);
        for (const BounceRecord& b : p.bounces)
            magnitude += glm::abs(glm::dvec3(b.emissionAdded())) + glm::abs(glm::dvec3(b.lightAdded())) +
                         glm::abs(glm::dvec3(b.stageAlbedoAdded()));
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(sum[c], double(p.value[c]), 1e-5 * magnitude[c] + 1e-12)
                << path << " channel " << c << " bounces " << p.bounces.size();
        if (p.bounces.empty()) continue;
        EXPECT_EQ(p.bounces[0].throughputBefore, glm::vec3(1.0f)) << path << ": the camera ray carries 1";
        for (std::size_t k = 0; k < p.bounces.size(); ++k) {
            const BounceRecord& b = p.bounces[k];
            const std::string at = path + " bounce " + std::to_string(k);
            const bool last = k + 1 == p.bounces.size();
            n.stageAlbedo += b.hasStageAlbedo;
            if (b.hasStageAlbedo) {
                EXPECT_TRUE(last) << at << ": render.stage primary ends at the first hit";
            }
            n.notCounted += (!b.emissionCounted && glm::length(b.emission * b.emissionWeight + b.stageAlbedo) > 0.0f) +
                            (!b.lightCounted && glm::length(b.lightContribution) > 0.0f);
            if (!b.sampled) {
                EXPECT_TRUE(last) << at << ": no direction sampled, yet the path goes on";
                continue;
            }
            if (b.lobe >= 0 && b.lobe < 5) ++n.lobes[b.lobe];
            if (b.lobe == 0) {   // no valid direction: the path ends here
                EXPECT_TRUE(last) << at;
                continue;
            }
            if (b.delta) {
                ++n.deltaSamples;
            } else if (b.pdf > 0.0f && b.cosTheta > 0.0f) {
                // The weight the throughput is multiplied by is f·|cosθ|/pdf for non-delta lobes.
                expectNearRelative(b.weight, b.f * b.cosTheta / b.pdf, 1e-5f, at + " weight = f |cos| / pdf");
                ++n.weightsChecked;
            }
            if (b.rrOutcome >= 0) ++n.roulette;
            if (b.rrOutcome == 0) {
                EXPECT_TRUE(last) << at << ": roulette ended the path";
                EXPECT_EQ(b.throughputAfter, glm::vec3(0.0f)) << at;
                continue;
            }
            if (last) {
                // Sampled, not killed, yet no next bounce: the geometric surface disagreed with
                // the lobe's side, and the path ended without a throughput after.
                EXPECT_EQ(b.throughputAfter, glm::vec3(0.0f)) << at;
                continue;
            }
            // after = before × weight / q, q = 1 when roulette was not played.
            const float q = b.rrOutcome == 1 ? b.rrProbability : 1.0f;
            if (b.rrOutcome == 1) {
                EXPECT_GT(q, 0.0f) << at;
            }
            expectNearRelative(b.throughputAfter, b.throughputBefore * b.weight / q, 1e-6f,
                               at + " throughput after = before x weight / q");
            // The next bounce carries exactly this throughput.
            EXPECT_EQ(p.bounces[k + 1].throughputBefore, b.throughputAfter) << at << ": next bounce's throughput before";
            ++n.chained;
        }
    }
    return n;
}

} // namespace raylab::test
