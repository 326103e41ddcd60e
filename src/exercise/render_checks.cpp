// The render check: exercises/render_check.json rendered with the pupil's function and with the
// reference at equal spp. A correct function may draw other random numbers (another disk map), so
// the difference is measured against the noise: the relMSE between two reference renders of
// different seeds.
#include "exercise/checks.h"
#include "exercise/check_support.h"
#include "exercise/manifest.h"

#include "bench/error_metrics.h"
#include "io/image_io.h"
#include "render/progressive_render.h"
#include "scene/scene_loader.h"

#include <cmath>

namespace raylab {
using namespace exercise;
namespace {

// A pupil's render may differ from the reference by up to this factor times the noise between
// two reference renders (their relMSE); a correct function that samples differently stays near 1.
constexpr double kNoiseFactor = 1.5;

Image render(const Scene& scene, const ShaderDefines& defines, std::uint32_t seed) {
    TracerOptions o;
    o.extraDefines = defines;
    PathTracer tracer(o);
    Scene s = scene;
    s.render.seed = seed;
    tracer.setScene(s);
    renderProgressively(tracer, s.render);
    return tracer.readImage();
}

} // namespace

CheckResult checkRenderDiff(const CheckContext& context) {
    const Scene scene = loadScene(exerciseDirectory() / "render_check.json");
    const ShaderDefines pupil = {{context.slot, "\"" + std::filesystem::absolute(context.pupilFile).string() + "\""}};
    CheckResult res{"render-diff", false, "", "", ""};
    Image mine;
    try {
        mine = render(scene, pupil, 1);
    } catch (const ShaderError& e) {
        res.message = std::string("the tracer does not compile with this function: ") + e.what();
        return res;
    }
    const Image reference = render(scene, {}, 1);
    const Image other = render(scene, {}, 2);
    const ImageError err = imageError(mine, reference);
    const ImageError noise = imageError(other, reference);
    const double meanRef = imageMean(reference), meanMine = imageMean(mine);
    const double relMean = std::abs(meanMine - meanRef) / meanRef;
    res.pass = std::isfinite(err.relMse) && err.relMse <= kNoiseFactor * noise.relMse;
    res.numbers = "relMSE against the reference " + num(err.relMse) + ", noise (reference, other seed) " + num(noise.relMse) +
                  ", image mean " + num(meanMine) + " vs " + num(meanRef) + " (relative difference " + num(relMean) + "), " +
                  std::to_string(scene.render.spp) + " spp";
    if (!context.imageDir.empty()) {
        Image diff(reference.width, reference.height);
        for (std::size_t i = 0; i < diff.rgba.size(); ++i)
            diff.rgba[i] = (i % 4 == 3) ? 1.0f : std::abs(mine.rgba[i] - reference.rgba[i]);
        std::filesystem::create_directories(context.imageDir);
        res.image = (context.imageDir / (context.exercise + "-difference.exr")).string();
        RenderMetadata meta;
        meta.spp = std::uint64_t(scene.render.spp);
        writeImage(res.image, diff, meta, DisplayTransform{0.0f, ToneMap::Clamp});
    }
    if (!res.pass)
        res.message = "the render differs from the reference by more than its noise (relMSE " + num(err.relMse) + " > " +
                      num(kNoiseFactor) + " × " + num(noise.relMse) + ")";
    return res;
}

} // namespace raylab
