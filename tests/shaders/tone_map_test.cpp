#include "shaders/include/tone_map.glsl"

#include <gtest/gtest.h>

using namespace raylab::glsl;

TEST(ShaderToneMap, SrgbEncodingEndpointsAndKnownValues) {
    EXPECT_FLOAT_EQ(srgbEncode(0.0f), 0.0f);
    EXPECT_NEAR(srgbEncode(1.0f), 1.0f, 1e-6f);
    EXPECT_NEAR(srgbEncode(0.5f), 0.735357f, 1e-5f);          // IEC 61966-2-1
    EXPECT_NEAR(srgbEncode(0.002f), 0.002f * 12.92f, 1e-7f);   // linear toe
    EXPECT_FLOAT_EQ(srgbEncode(7.0f), 1.0f);                   // clamped
}

TEST(ShaderToneMap, OperatorsAreMonotoneAndBounded) {
    for (int op : {TONE_MAP_CLAMP, TONE_MAP_REINHARD, TONE_MAP_ACES_FIT}) {
        float previous = -1.0f;
        for (float x = 0.0f; x < 100.0f; x = x * 1.1f + 0.001f) {
            const float v = displayValue(x, 0.0f, op);
            EXPECT_GE(v, previous) << "op " << op << " x " << x;
            EXPECT_LE(v, 1.0f);
            previous = v;
        }
    }
    EXPECT_NEAR(toneReinhard(1.0f), 0.5f, 1e-7f);
    EXPECT_NEAR(toneAcesFit(1.0f), 0.8038f, 1e-3f);   // Narkowicz's fit at 1
    // Exposure in stops: +1 EV doubles the linear value before the curve.
    EXPECT_FLOAT_EQ(displayValue(0.125f, 1.0f, TONE_MAP_CLAMP), displayValue(0.25f, 0.0f, TONE_MAP_CLAMP));
}
