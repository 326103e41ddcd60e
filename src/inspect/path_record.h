#pragma once
// One recorded sample path of the pixel path inspector: every term of the estimator at every
// bounce, as the tracer computed them (shaders/include/path_record.glsl), read back by
// PathInspector. The sample's value is Σ_k throughputBefore_k · (emission_k · w_k + light_k), over
// the terms that count (all but under the viewer's bounce views, which keep some bounces only);
// under render.stage primary it is the first hit's albedo (stageAlbedo).
#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace raylab {

// Must match shaders/include/bsdf_sample.glsl's LOBE_*.
std::string lobeName(int lobe);

enum class LightStatus { None = -1, Occluded = 0, Visible = 1, Zero = 2 };   // Zero: f·L = 0 (a light seen from behind) or no direction
std::string lightStatusName(LightStatus s);

struct BounceRecord {
    // The segment that arrives here (bounce 0: the camera ray).
    glm::vec3 origin{0.0f};
    glm::vec3 direction{0.0f};     // unit
    bool hit = false;              // false: the ray left the scene (the sky)
    float distance = 0.0f;         // to the hit
    // The surface (when hit).
    glm::vec3 position{0.0f};
    int primitive = -1;            // sphere index or global triangle index
    int instance = -1;             // top-level instance (GPU order)
    int material = -1;
    glm::vec3 normal{0.0f};        // geometric
    glm::vec3 shadingNormal{0.0f}; // the BSDF frame's z (turned to the geometric normal's side)
    // Emission found here (an emitter, or the sky for a miss) and its MIS weight.
    glm::vec3 emission{0.0f};
    float emissionWeight = 0.0f;
    // render.stage primary: the first hit's flat albedo, that stage's whole estimate (no light at all).
    bool hasStageAlbedo = false;
    glm::vec3 stageAlbedo{0.0f};
    // Whether this bounce's emission (or stage albedo) and its light sample count toward the value:
    // the viewer's bounce views (debug view bounce k, direct, indirect) keep some bounces only; a
    // light sample taken here counts as bounce k + 1.
    bool emissionCounted = true;
    bool lightCounted = true;
    // Throughput arriving here.
    glm::vec3 throughputBefore{0.0f};
    // Next-event estimation from here.
    LightStatus lightStatus = LightStatus::None;
    int lightIndex = -1;           // light sampled: spheres, then triangles, then Scene::lights; -1 the sky
    std::string lightName;         // inspect/light_names.h: "sky", "sphere light 0", "spot 1", ...
    bool lightDelta = false;       // a point, spot or disc-less distant light: no BSDF ray can hit it
    glm::vec3 lightDirection{0.0f};
    float lightDistance = -1.0f;   // to the light's surface or point; -1: the sky or a distant light (no end point)
    glm::vec3 lightRadiance{0.0f};
    glm::vec3 lightFCos{0.0f};     // f·|cosθ| towards the light
    float lightCosTheta = 0.0f;
    float lightPdf = 0.0f;         // the density it was drawn with (light choice included)
    float lightBsdfPdf = 0.0f;     // the BSDF's density for that direction (MIS)
    float lightMisPdf = 0.0f;      // the light's density as MIS weighs it (a delta light: FLOAT_MAX, w = 1)
    float lightMisWeight = 0.0f;
    glm::vec3 lightContribution{0.0f};   // f·|cosθ|·Le·w/pdf, throughput not included
    // The BSDF sample that continues the path (when sampled).
    bool sampled = false;
    glm::vec3 sampledDirection{0.0f};
    int lobe = -1;                 // LOBE_*; 0 = no valid direction (the path ends)
    float lobeProbability = 0.0f;
    glm::vec3 f{0.0f};             // for delta lobes: the weight
    float cosTheta = 0.0f;
    float pdf = 0.0f;
    glm::vec3 weight{0.0f};        // f·|cosθ|/pdf
    bool delta = false;
    glm::vec3 throughputAfter{0.0f};   // after the BSDF weight and Russian roulette (0: the path ended)
    // Russian roulette after this bounce.
    float rrProbability = 0.0f;    // survival probability q
    int rrOutcome = -1;            // -1 not played, 0 killed, 1 survived

    // What each term adds to the value (0 when it does not count).
    glm::vec3 emissionAdded() const { return emissionCounted ? throughputBefore * emission * emissionWeight : glm::vec3(0.0f); }
    glm::vec3 stageAlbedoAdded() const { return emissionCounted ? throughputBefore * stageAlbedo : glm::vec3(0.0f); }
    glm::vec3 lightAdded() const { return lightCounted ? throughputBefore * lightContribution : glm::vec3(0.0f); }
    // Where the shadow ray ends: the light's surface, or `skyLength` along it for the sky.
    glm::vec3 shadowTarget(float skyLength) const {
        return position + lightDirection * (lightDistance >= 0.0f ? lightDistance : skyLength);
    }
};

// The light sample's density as MIS sees it: "delta (never hit by BSDF rays)" for a delta light,
// else the number.
std::string lightMisPdfText(const BounceRecord& b);

struct PathRecord {
    int x = 0;                     // image pixel, top-left origin
    int y = 0;
    std::uint64_t sample = 0;      // the sample's index in the pixel's sequence
    glm::vec3 value{0.0f};         // what the sample added to the pixel's mean (before the NaN guard)
    bool truncated = false;        // more bounces than the buffer held
    std::vector<BounceRecord> bounces;
    // Σ throughputBefore · (emission · w + stage albedo + light contribution) over the terms that
    // count, summed in double.
    glm::dvec3 sumOfTerms() const;
};

} // namespace raylab
