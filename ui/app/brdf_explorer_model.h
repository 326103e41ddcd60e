#pragma once
// The BRDF explorer's state (model of its panel): which material, the incoming direction, the
// lobes switched on, and the results for them (inspect/brdf_explorer.h): the polar curve, the
// hemisphere maps, the GPU sampler's directions and their χ² verdict. Recomputed only when an
// input changes. No ImGui here.
#include "inspect/brdf_explorer.h"
#include "selftest/gpu_sampler.h"
#include "inspect/path_record.h"

#include <memory>
#include <string>
#include <vector>

namespace raylab::ui {

class Viewer;

class BrdfExplorerModel {
public:
    bool panelOpen = false;
    int material = -1;        // -1: the selected object's material (Selection::editedMaterial; else the first)
    float thetaDeg = 45.0f;   // incoming (wo) direction in the local frame; > 90: from inside
    float phiDeg = 0.0f;
    LobeToggles lobes;
    int sampleCount = 20000;
    unsigned seed = 1;
    int cells = 16;           // χ² grid: cells × cells per hemisphere
    double alpha = 0.01;      // significance of the verdict
    bool mapPdf = false;      // heat maps: the sampling pdf instead of f·cosθ

    // The material index in use for this scene (-1 when the scene has none).
    int resolvedMaterial(const Viewer& viewer) const;
    glm::vec3 wo() const { return directionFromAngles(thetaDeg, phiDeg); }
    // Takes the material and incoming direction of an inspected bounce (the BSDF's local frame).
    void fromBounce(const BounceRecord& bounce);
    // Recomputes what changed; logs GPU errors to error().
    void update(Viewer& viewer);

    const glsl::BsdfParams& params() const { return params_; }
    const std::vector<PolarPoint>& polar() const { return polar_; }
    const HemisphereMap& map() const { return mapPdf ? pdfMap_ : map_; }
    const std::vector<GpuSample>& samples() const { return samples_; }
    const SamplerTest& test() const { return test_; }
    bool hasResults() const { return !polar_.empty(); }
    const std::string& error() const { return error_; }

private:
    std::unique_ptr<GpuSampler> sampler_;
    glsl::BsdfParams params_{};
    std::vector<float> key_;   // the inputs the results are for
    std::vector<PolarPoint> polar_;
    HemisphereMap map_;
    HemisphereMap pdfMap_;
    std::vector<GpuSample> samples_;
    SamplerTest test_;
    std::string error_;
};

} // namespace raylab::ui
