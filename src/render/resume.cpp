#include "render/resume.h"

#include "scene/parameters.h"
#include "scene/scene_writer.h"

#include <cstdint>
#include <cstdio>
#include <string_view>

namespace raylab {
namespace {

class Fnv1a {
public:
    void add(const void* data, std::size_t bytes) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < bytes; ++i) h_ = (h_ ^ p[i]) * 0x100000001b3ull;
    }
    template <class T>
    void addVector(const std::vector<T>& v) {
        const std::uint64_t n = v.size();
        add(&n, sizeof n);
        add(v.data(), v.size() * sizeof(T));
    }
    std::string hex() const {
        char buf[17];
        std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h_));
        return buf;
    }

private:
    std::uint64_t h_ = 0xcbf29ce484222325ull;
};

std::string samplerName(const Scene& scene) {
    return formatValue(*findParameter("render.sampler"), std::int64_t(scene.render.sampler));
}

} // namespace

std::string settingsHash(const Scene& scene) {
    nlohmann::json doc = sceneToJson(scene);
    if (doc.contains("render")) {
        doc["render"].erase("spp");
        doc["render"].erase("time");
    }
    Fnv1a h;
    const std::string text = doc.dump();
    h.add(text.data(), text.size());
    for (const Mesh& m : scene.meshes) {
        h.addVector(m.positions);
        h.addVector(m.normals);
        h.addVector(m.uvs);
        h.addVector(m.triangles);
        h.addVector(m.triangleMaterials);
    }
    for (const Texture& t : scene.textures)
        for (const MipLevel& l : t.levels) h.addVector(l.texels);
    return h.hex();
}

ResumePoint readResumePoint(const std::filesystem::path& exr, const Scene& scene, const std::string& tracer) {
    const std::string file = exr.string();
    ResumePoint p;
    p.meta = readRenderMetadata(exr);
    const RenderMetadata& m = p.meta;
    const RenderSettings& r = scene.render;
    const auto differs = [&](const std::string& what, const std::string& recorded, const std::string& given) {
        return ImageIoError(file + ": error: cannot resume: " + what + " is " + recorded + " in the EXR but " + given +
                            " for " + scene.sourcePath.string() + " (resume with the scene and settings it was made with)");
    };
    if (m.version != RAYLAB_VERSION) throw differs("raylab:version", m.version, RAYLAB_VERSION);
    p.adaptive = readAdaptiveState(exr);
    if (adaptiveInEffect(r) && !p.adaptive)
        throw ImageIoError(file + ": error: cannot resume: render.adaptive is in effect for " + scene.sourcePath.string() +
                           " but the EXR has no adaptive.samples channel: it was rendered with even sampling (resume it "
                           "with --set render.adaptive=false)");
    if (!adaptiveInEffect(r) && p.adaptive)
        throw ImageIoError(file + ": error: cannot resume: the EXR is an adaptive render's (it has the channel "
                           "adaptive.samples) but render.adaptive is not in effect for " + scene.sourcePath.string() +
                           " (resume it with render.adaptive true and the sobol or independent sampler)");
    if (m.tracer != tracer) throw differs("raylab:tracer", m.tracer, "--tracer " + tracer);
    if (m.seed != r.seed) throw differs("raylab:seed", std::to_string(m.seed), "render.seed " + std::to_string(r.seed));
    if (m.sampler != samplerName(scene)) throw differs("raylab:sampler", m.sampler, "render.sampler " + samplerName(scene));
    if (m.rpp != r.rpp) throw differs("raylab:rpp", std::to_string(m.rpp), "render.rpp " + std::to_string(r.rpp));
    if (m.settingsHash != settingsHash(scene))
        throw ImageIoError(file + ": error: cannot resume: raylab:settings_hash differs: the scene " +
                           scene.sourcePath.string() + " or its settings (--set, --width, ...) are not those the EXR was made with");
    if (std::uint64_t(r.spp) < m.spp)
        throw ImageIoError(file + ": error: cannot resume: it holds " + std::to_string(m.spp) +
                           " spp already, more than the target render.spp " + std::to_string(r.spp));
    if (r.sampler == SamplerKind::Stratified && std::uint64_t(r.spp) != m.targetSpp)
        throw ImageIoError(file + ": error: cannot resume: the stratified sampler lays its strata out for the target " +
                           "of the run, raylab:target_spp " + std::to_string(m.targetSpp) + ", not render.spp " +
                           std::to_string(r.spp) + " (resume it to --spp " + std::to_string(m.targetSpp) + ")");
    p.image = readImage(exr);
    if (p.image.width != r.width || p.image.height != r.height)
        throw differs("the image size", std::to_string(p.image.width) + "x" + std::to_string(p.image.height),
                      std::to_string(r.width) + "x" + std::to_string(r.height));
    if (p.adaptive) {
        // The counts decide every later sample's index: they must be the render's own.
        const AdaptiveBlocks blocks{r.width, r.height};
        std::vector<std::uint64_t> counts;
        try {
            counts = blockSamplesOf(blocks, p.adaptive->samples);
        } catch (const std::invalid_argument& e) {
            throw ImageIoError(file + ": error: cannot resume: adaptive.samples: " + e.what());
        }
        const std::uint64_t mean = pathsIn(blocks, counts) / (std::uint64_t(r.width) * std::uint64_t(r.height));
        if (mean != m.spp)
            throw ImageIoError(file + ": error: cannot resume: adaptive.samples averages " + std::to_string(mean) +
                               " samples per pixel, but raylab:spp is " + std::to_string(m.spp));
    }
    return p;
}

} // namespace raylab
