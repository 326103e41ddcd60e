// The viewer's one-click self-test, run headless (OSMesa): it passes on a correct driver and
// tracer, and it can fail: fed a wrong pdf it reports FAIL with the numbers.
#include "selftest/self_test.h"

#include "shaders/include/light_sampling.glsl"

#include "support/gl_test.h"

#include <cmath>

using namespace raylab;

class SelfTestTest : public test::GlTest {};

TEST_F(SelfTestTest, PassesOnThisDriver) {
    const SelfTestReport r = runSelfTest();
    // Furnace, cosine hemisphere, three GGX cases, rough glass, the sphere light's cone.
    ASSERT_EQ(r.results.size(), 7u);
    for (const SelfTestResult& t : r.results) {
        EXPECT_TRUE(t.pass) << describe(t);
        if (t.kind == "chi2") {
            EXPECT_GT(t.dof, 10) << t.name;
            EXPECT_NEAR(t.alpha, 1.0 - std::pow(0.99, 1.0 / 6.0), 1e-12);   // Šidák over six χ² tests
        }
    }
    EXPECT_EQ(r.results[5].name, "rough glass a=0.25 cos=0.7");
    EXPECT_EQ(r.results[6].name, "sphere light cone");
    EXPECT_TRUE(r.pass());
    EXPECT_FALSE(r.driver.empty());
    EXPECT_EQ(describe(r.results[0]).rfind("PASS furnace: max deviation", 0), 0u) << describe(r.results[0]);
}

TEST_F(SelfTestTest, FailsWhenThePdfIsWrong) {
    SelfTestOptions o;
    o.cosinePdf = [](float c) { return c > 0.0f ? 0.5 / M_PI : 0.0; };   // uniform, not cosine
    o.bsdfPdf = [](const glsl::BsdfParams& m, glm::vec3 wo, glm::vec3 wi) {
        glsl::BsdfParams wrong = m;
        wrong.alpha = m.alpha * 1.3f;   // a pdf for a rougher surface than the sampler's
        return double(glsl::bsdfPdf(wrong, wo, wi));
    };
    // The density of a sphere 10% larger than the one sampled.
    o.sphereConePdf = [](glm::vec3 c, float radius) { return double(glsl::sphereConePdf(glm::vec3(0.0f), c, 1.1f * radius)); };
    const SelfTestReport r = runSelfTest(o);
    ASSERT_EQ(r.results.size(), 7u);
    EXPECT_TRUE(r.results[0].pass) << "the furnace does not use the pdfs";
    for (std::size_t i = 1; i < r.results.size(); ++i) {
        EXPECT_FALSE(r.results[i].pass) << describe(r.results[i]);
        EXPECT_LT(r.results[i].pValue, r.results[i].alpha);
        EXPECT_EQ(describe(r.results[i]).rfind("FAIL ", 0), 0u);
    }
    EXPECT_FALSE(r.pass());
}
