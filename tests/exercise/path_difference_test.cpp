// The render check's path comparison: the first term where a pupil's recorded paths part from the
// reference's, in the order the tracer computes them.
#include "exercise/path_difference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace raylab::exercise {
namespace {

PathRecord twoBouncePath() {
    PathRecord p;
    p.sample = 7;
    p.value = glm::vec3(0.25f, 0.5f, 0.125f);
    BounceRecord camera;
    camera.origin = glm::vec3(0.0f, 1.0f, 5.0f);
    camera.direction = glm::normalize(glm::vec3(0.0f, -0.1f, -1.0f));
    camera.hit = true;
    camera.distance = 4.5f;
    camera.primitive = 3;
    camera.f = glm::vec3(0.8f / 3.14159265f);
    camera.pdf = 0.3f;
    BounceRecord second = camera;
    second.distance = 2.0f;
    p.bounces = {camera, second};
    return p;
}

} // namespace

TEST(PathDifference, EqualPathsAgreeAndSaySoInWords) {
    const std::vector<PathRecord> a = {twoBouncePath(), twoBouncePath()};
    const PathDifference d = firstPathDifference(a, a);
    EXPECT_FALSE(d.found);
    EXPECT_NE(describe(d).find("agree term by term"), std::string::npos) << describe(d);
}

TEST(PathDifference, RoundingOfACorrectFunctionIsNoDifference) {
    std::vector<PathRecord> mine = {twoBouncePath()}, reference = mine;
    mine[0].bounces[0].distance *= 1.0f + 1e-5f;
    mine[0].bounces[1].f *= 1.0f - 1e-5f;
    EXPECT_FALSE(firstPathDifference(mine, reference).found);
}

TEST(PathDifference, TheFirstTermThatDiffersIsNamedWithBothValues) {
    std::vector<PathRecord> mine = {twoBouncePath()}, reference = mine;
    mine[0].bounces[1].f = glm::vec3(0.8f);   // a Lambert BRDF without its 1/π, at the second hit
    PathDifference d = firstPathDifference(mine, reference);
    ASSERT_TRUE(d.found);
    EXPECT_EQ(d.sample, 7u);
    EXPECT_EQ(d.bounce, 1);
    EXPECT_EQ(d.term, "the BRDF value f of the sampled direction");
    EXPECT_EQ(describe(d), "sample 7, bounce 1: the BRDF value f of the sampled direction is (0.8, 0.8, 0.8) with your "
                           "function and (0.254648, 0.254648, 0.254648) with the reference");
    // An earlier term wins: the camera ray's hit distance, before any BRDF.
    mine[0].bounces[0].distance = 4.1f;
    d = firstPathDifference(mine, reference);
    EXPECT_EQ(d.bounce, 0);
    EXPECT_EQ(d.term, "the hit distance t");
    EXPECT_NE(describe(d).find("the camera ray (bounce 0): the hit distance t is 4.1 with your function and 4.5"),
              std::string::npos)
        << describe(d);
}

TEST(PathDifference, AMissANaNAndAShorterPathAreDifferences) {
    std::vector<PathRecord> mine = {twoBouncePath()}, reference = mine;
    mine[0].bounces[0].hit = false;
    EXPECT_EQ(firstPathDifference(mine, reference).term, "whether the ray hits");
    mine = reference;
    mine[0].bounces[1].pdf = std::numeric_limits<float>::quiet_NaN();
    EXPECT_EQ(firstPathDifference(mine, reference).term, "the pdf of the sampled direction");
    mine = reference;
    mine[0].bounces.pop_back();
    const PathDifference d = firstPathDifference(mine, reference);
    EXPECT_EQ(d.term, "the number of bounces");
    EXPECT_EQ(d.mine, "1");
    EXPECT_EQ(d.reference, "2");
    // The same bounces and another value: the difference is in the value.
    mine = reference;
    mine[0].value *= 2.0f;
    EXPECT_EQ(firstPathDifference(mine, reference).term, "the sample's value");
}

} // namespace raylab::exercise
