#pragma once
// The buffer layout of shaders/include/path_record.glsl (PR_* there): vec4 slots per bounce
// record and per path. Keep the two in step.
namespace raylab::path_layout {

constexpr int kBounceVec4s = 19;
constexpr int kOrigin = 0, kDirection = 1, kPosition = 2, kNormal = 3, kShading = 4, kEmission = 5,
              kBetaBefore = 6, kSampled = 7, kF = 8, kWeight = 9, kBetaAfter = 10, kRr = 11, kLight = 12,
              kLightDir = 13, kLightTerms = 14, kLightF = 15, kLightLe = 16, kCounted = 17, kStageAlbedo = 18;
constexpr int kPathVec4s = 4;

} // namespace raylab::path_layout
