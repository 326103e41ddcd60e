// The render check: exercises/render_check.json rendered with the pupil's function and with the
// reference at equal spp. A correct function may draw other random numbers (another disk map), so
// the difference is measured against the noise: the relMSE between two reference renders of
// different seeds. On a failure the path inspector records the same samples of the pixel where the
// renders differ most with both functions, and the first term where they part is the message.
#include "exercise/checks.h"
#include "exercise/check_support.h"
#include "exercise/manifest.h"
#include "exercise/path_difference.h"

#include "bench/error_metrics.h"
#include "inspect/path_export.h"
#include "inspect/path_inspector.h"
#include "io/image_io.h"
#include "render/progressive_render.h"
#include "scene/scene_loader.h"

#include <algorithm>
#include <cmath>

namespace raylab {
using namespace exercise;
namespace {

// A pupil's render may differ from the reference by up to this factor times the noise between
// two reference renders (their relMSE); a correct function that samples differently stays near 1.
constexpr double kNoiseFactor = 1.5;
// Samples of the chosen pixel the path inspector records with each function.
constexpr int kInspectedPaths = 16;
// Half the side of the box the differences are summed over when the pixel is chosen: one noisy
// pixel must not win over a region that is wrong.
constexpr int kPickRadius = 2;

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

float difference(const Image& a, const Image& b, int x, int y) {
    const glm::vec3 d = glm::abs(a.rgb(x, y) - b.rgb(x, y));
    return d.r + d.g + d.b;
}

// Summed over a box around each pixel, where the pupil's render is farther from the reference than
// the other-seed reference is (the noise alone); the pixel of the largest excess.
glm::ivec2 mostDifferentPixel(const Image& mine, const Image& reference, const Image& other) {
    glm::ivec2 best(0);
    double bestExcess = -1.0;
    for (int y = 0; y < reference.height; ++y)
        for (int x = 0; x < reference.width; ++x) {
            double excess = 0.0;
            for (int v = std::max(0, y - kPickRadius); v <= std::min(reference.height - 1, y + kPickRadius); ++v)
                for (int u = std::max(0, x - kPickRadius); u <= std::min(reference.width - 1, x + kPickRadius); ++u)
                    excess += double(difference(mine, reference, u, v)) - double(difference(other, reference, u, v));
            if (!std::isfinite(excess)) excess = 1e30;   // a NaN or infinity in the pupil's render wins
            if (excess > bestExcess) {
                bestExcess = excess;
                best = {x, y};
            }
        }
    return best;
}

std::vector<PathRecord> recordPaths(const Scene& scene, const ShaderDefines& defines, glm::ivec2 pixel) {
    PathInspector inspector(PathInspector::kDefaultMaxRecords, defines);
    Scene s = scene;
    s.render.seed = 1;
    inspector.setScene(s);
    return inspector.record(pixel.x, pixel.y, kInspectedPaths);
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
    if (res.pass) return res;
    res.message = "the render differs from the reference by more than its noise (relMSE " + num(err.relMse) + " > " +
                  num(kNoiseFactor) + " × " + num(noise.relMse) + ")";
    const glm::ivec2 pixel = mostDifferentPixel(mine, reference, other);
    res.pixelX = pixel.x;
    res.pixelY = pixel.y;
    res.scene = (exerciseDirectory() / "render_check.json").string();
    const std::string at = "; the path inspector at pixel (" + std::to_string(pixel.x) + ", " + std::to_string(pixel.y) +
                           "), where the two differ most: ";
    try {
        const std::vector<PathRecord> minePaths = recordPaths(scene, pupil, pixel);
        const std::vector<PathRecord> referencePaths = recordPaths(scene, {}, pixel);
        res.message += at + describe(firstPathDifference(minePaths, referencePaths));
        if (!context.imageDir.empty()) {
            writePaths(context.imageDir / (context.exercise + "-paths-yours.json"), minePaths);
            writePaths(context.imageDir / (context.exercise + "-paths-reference.json"), referencePaths);
        }
    } catch (const std::exception& e) {
        res.message += at + "could not record the paths (" + e.what() + ")";
    }
    return res;
}

} // namespace raylab
