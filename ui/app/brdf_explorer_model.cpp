#include "app/brdf_explorer_model.h"

#include "app/viewer.h"
#include "shaders/include/frame.glsl"

#include <algorithm>

namespace raylab::ui {

int BrdfExplorerModel::resolvedMaterial(const Viewer& viewer) const {
    const Scene& s = viewer.scene();
    if (s.materials.empty()) return -1;
    if (material >= 0 && material < int(s.materials.size())) return material;
    const int m = viewer.selection.editedMaterial();   // the selected sphere's or mesh's (under the click)
    return m >= 0 && m < int(s.materials.size()) ? m : 0;
}

void BrdfExplorerModel::fromBounce(const BounceRecord& b) {
    if (!b.hit) return;
    material = b.material;
    const glsl::Frame frame = glsl::frameFromNormal(b.shadingNormal);
    const glm::vec2 a = anglesFromDirection(glsl::frameToLocal(frame, -b.direction));
    thetaDeg = a.x;
    phiDeg = a.y;
}

void BrdfExplorerModel::update(Viewer& viewer) {
    const int m = resolvedMaterial(viewer);
    if (m < 0) return;
    params_ = explorerBsdf(viewer.scene().materials[std::size_t(m)], lobes, viewer.scene().render);
    thetaDeg = std::clamp(thetaDeg, 0.0f, 179.0f);
    sampleCount = std::clamp(sampleCount, 1000, 1 << 20);
    cells = std::clamp(cells, 4, 64);
    const glsl::BsdfParams& p = params_;
    const std::vector<float> key = {p.albedo.x, p.albedo.y, p.albedo.z, p.f0.x, p.f0.y, p.f0.z, p.alpha,
                                    p.transmission, p.ior, float(p.diffuseSampling), float(p.ggxSampling), thetaDeg, phiDeg, float(sampleCount), float(seed),
                                    float(cells), float(alpha)};
    if (key == key_) return;
    key_ = key;
    const glm::vec3 w = wo();
    polar_ = polarCurve(p, w, 360);
    map_ = hemisphereMap(p, w, 48);
    pdfMap_ = hemisphereMap(p, w, 48, MapQuantity::Pdf);
    try {
        if (!sampler_) sampler_ = std::make_unique<GpuSampler>();
        samples_ = sampler_->bsdf(p, w, unsigned(sampleCount), seed);
        test_ = testSampler(p, w, samples_, cells, alpha);
        error_.clear();
    } catch (const std::exception& e) {
        samples_.clear();
        test_ = SamplerTest{};
        error_ = e.what();
        viewer.log().error(std::string("BRDF explorer: ") + e.what());
    }
}

} // namespace raylab::ui
