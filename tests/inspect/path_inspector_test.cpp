// The pixel path inspector: the recorded terms reproduce each sample's value, the recorded path
// agrees with a CPU computation of the same path, and recording changes nothing in the image.
#include "inspect/path_checks.h"
#include "inspect/path_export.h"
#include "inspect/path_inspector.h"
#include "inspect/sample_points.h"
#include "shaders/include/bindings.glsl"
#include "shaders/include/frame.glsl"
#include "shaders/include/path_record_layout.glsl"
#include "shaders/include/sampling.glsl"
#include "shaders/include/sphere.glsl"
#include "render/path_tracer.h"
#include "scene/scene_loader.h"
#include "support/gl_test.h"
#include "../render/render_helpers.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace raylab::test {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

// Two Lambertian spheres (a ball on a big ground sphere) under a constant sky: every bounce of a
// path can be recomputed on the CPU from its recorded ray.
const char* kTwoSpheres = R"({
  "camera": { "position": [0, 1, 4], "look_at": [0, 0.6, 0], "up": [0, 1, 0], "fov": 40 },
  "render": { "width": 24, "height": 16, "rpp": 1, "spp": 1, "max_bounces": 6, "rr_depth": 2,
              "seed": 7, "nee": false },
  "sky": { "type": "constant", "color": [0.9, 1.0, 1.2], "strength": 1 },
  "materials": { "ground": { "albedo": [0.5, 0.6, 0.4] }, "ball": { "albedo": [0.8, 0.3, 0.2] } },
  "objects": [ { "type": "sphere", "center": [0, -100, 0], "radius": 100, "material": "ground" },
               { "type": "sphere", "center": [0, 0.7, 0], "radius": 0.7, "material": "ball" } ]
})";

// Nearest hit of a ray with the scene's spheres, in double: t, or -1 for a miss.
double intersectSpheres(const Scene& scene, glm::dvec3 o, glm::dvec3 d, int& which) {
    double best = -1.0;
    which = -1;
    for (std::size_t i = 0; i < scene.spheres.size(); ++i) {
        const Sphere& s = scene.spheres[i];
        const glm::dvec3 oc = o - glm::dvec3(s.center);
        const double b = glm::dot(oc, d), c = glm::dot(oc, oc) - double(s.radius) * s.radius;
        const double disc = b * b - c;
        if (disc < 0.0) continue;
        for (double t : {-b - std::sqrt(disc), -b + std::sqrt(disc)}) {
            if (t > 1e-6 * (1.0 + std::abs(b)) && (best < 0.0 || t < best)) {
                best = t;
                which = int(i);
                break;
            }
        }
    }
    return best;
}

void expectNear3(glm::vec3 a, glm::vec3 b, float tol, const std::string& what) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(a[i], b[i], tol) << what << " component " << i;
}

using PathInspectorTest = GlTest;

// Every scene case and every render stage: the recorded terms multiply out to the sample's value,
// and the throughput chains through the bounces (path_checks.h).
// ctest: slow
TEST_F(PathInspectorTest, RecordedTermsMultiplyOutToTheSampleValue) {
    struct Case {
        const char* scene;
        std::vector<std::string> overrides;
    };
    const std::vector<Case> cases = {
        {"lesson_one_sphere.json", {"render.nee=false"}},
        {"lesson_one_sphere.json", {"render.nee=true", "render.mis=true"}},
        {"lesson_one_sphere.json", {"render.nee=true", "render.mis=false"}},
        // GGX plastic and metals, rough and smooth glass, a mirror (spheres).
        {"materials.json", {"render.nee=true"}},
        {"materials.json", {"render.nee=false"}},
        // Meshes, an emissive triangle light.
        {"cornell_box.json", {"render.nee=true"}},
        // Every render stage (render.stage): primary returns the albedo, emission stops at the
        // first hit, lambert and ggx path-trace, textures and full on scenes that use them.
        {"materials.json", {"render.stage=primary"}},
        {"materials.json", {"render.stage=emission"}},
        {"materials.json", {"render.stage=lambert"}},
        {"materials.json", {"render.stage=ggx"}},
        {"material_textures.json", {"render.stage=textures"}},
        {"depth_of_field.json", {"render.stage=full"}},
    };
    PathCheckCounts total;
    int nonZero = 0, withLight = 0;
    for (const Case& c : cases) {
        std::vector<std::string> o = c.overrides;
        o.push_back("render.width=32");
        o.push_back("render.height=20");
        const Scene scene = loadScene(scenePath(c.scene), o);
        PathInspector inspector;
        inspector.setScene(scene);
        // The centre, two corners, and a row across the image (materials.json: one sphere each).
        std::vector<std::pair<int, int>> pixels = {{16, 10}, {5, 15}, {28, 3}};
        for (int x = 1; x < 32; x += 3) pixels.emplace_back(x, 12);
        const int stageAlbedoBefore = total.stageAlbedo;
        for (auto [x, y] : pixels) {
            const auto paths = inspector.record(x, y, 24, 3);
            ASSERT_EQ(paths.size(), 24u);
            const PathCheckCounts n = expectTermsMultiplyOut(
                paths, std::string(c.scene) + " " + o[0] + " pixel " + std::to_string(x) + "," + std::to_string(y));
            total.chained += n.chained;
            total.weightsChecked += n.weightsChecked;
            total.deltaSamples += n.deltaSamples;
            total.roulette += n.roulette;
            total.stageAlbedo += n.stageAlbedo;
            for (int l = 0; l < 5; ++l) total.lobes[l] += n.lobes[l];
            for (const PathRecord& p : paths) {
                EXPECT_EQ(p.x, x);
                ASSERT_FALSE(p.bounces.empty());
                nonZero += glm::length(p.value) > 0.0f;
                for (const BounceRecord& b : p.bounces) withLight += b.lightStatus == LightStatus::Visible;
                if (scene.render.stage == RenderStage::Primary) {
                    // The value is the first hit's albedo, and the record says so.
                    ASSERT_EQ(p.bounces.size(), 1u);
                    const BounceRecord& b = p.bounces[0];
                    EXPECT_EQ(b.hasStageAlbedo, b.hit);
                    if (b.hit) {
                        EXPECT_EQ(p.value, scene.materials[std::size_t(b.material)].albedo);
                    }
                } else if (scene.render.stage == RenderStage::Emission) {
                    EXPECT_EQ(p.bounces.size(), 1u) << "emission stops at the first hit";
                }
            }
        }
        if (scene.render.stage == RenderStage::Primary) {
            EXPECT_GT(total.stageAlbedo - stageAlbedoBefore, 100);
        } else {
            EXPECT_EQ(total.stageAlbedo, stageAlbedoBefore) << c.scene << ": only the primary stage records an albedo";
        }
    }
    // The checks are not vacuous: paths carry light, light samples were taken and seen, every
    // lobe was sampled (diffuse, specular, glass reflection and transmission, delta and not),
    // throughputs were chained, and roulette was played.
    EXPECT_GT(nonZero, 100);
    EXPECT_GT(withLight, 50);
    for (int lobe = 1; lobe <= 4; ++lobe) EXPECT_GT(total.lobes[lobe], 20) << lobeName(lobe);
    EXPECT_GT(total.weightsChecked, 1000);
    EXPECT_GT(total.deltaSamples, 50);
    EXPECT_GT(total.chained, 1000);
    EXPECT_GT(total.roulette, 100);
}

TEST_F(PathInspectorTest, RecordedPathMatchesACpuComputation) {
    const Scene scene = parseScene(kTwoSpheres, "two_spheres.json");
    PathInspector inspector;
    inspector.setScene(scene);
    int bouncesChecked = 0, killed = 0, survived = 0;
    for (auto [x, y] : {std::pair{12, 10}, std::pair{12, 14}, std::pair{3, 2}}) {
        const auto paths = inspector.record(x, y, 48, 0);
        for (const PathRecord& p : paths) {
            ASSERT_FALSE(p.bounces.empty());
            // The camera ray starts at the camera.
            expectNear3(p.bounces[0].origin, scene.camera.position, 1e-6f, "camera origin");
            glm::dvec3 beta(1.0), value(0.0);
            for (std::size_t k = 0; k < p.bounces.size(); ++k) {
                const BounceRecord& b = p.bounces[k];
                const std::string where = "pixel " + std::to_string(x) + "," + std::to_string(y) + " sample " +
                                          std::to_string(p.sample) + " bounce " + std::to_string(k);
                expectNear3(b.throughputBefore, glm::vec3(beta), 1e-5f, where + " throughput before");
                int sphere = -1;
                const double t = intersectSpheres(scene, glm::dvec3(b.origin), glm::dvec3(b.direction), sphere);
                ASSERT_EQ(b.hit, t > 0.0) << where;
                if (!b.hit) {
                    expectNear3(b.emission, scene.sky.color * scene.sky.strength, 1e-6f, where + " sky");
                    EXPECT_EQ(b.emissionWeight, 1.0f) << where;
                    value += beta * glm::dvec3(b.emission);
                    EXPECT_EQ(k + 1, p.bounces.size()) << where << ": a miss ends the path";
                    break;
                }
                const Sphere& s = scene.spheres[std::size_t(sphere)];
                const glm::dvec3 pos = glm::dvec3(b.origin) + t * glm::dvec3(b.direction);
                const float scale = 1e-4f * (1.0f + float(glm::length(pos)));
                expectNear3(b.position, glm::vec3(pos), scale, where + " hit point");
                EXPECT_NEAR(b.distance, t, 1e-4 * (1.0 + t)) << where;
                const glm::vec3 n = glm::normalize(glm::vec3(pos) - s.center);
                expectNear3(b.normal, n, 1e-4f, where + " geometric normal");
                EXPECT_EQ(b.material, s.material) << where;
                EXPECT_EQ(b.primitive, sphere) << where;
                // Outside a sphere the shading frame is the outward normal.
                expectNear3(b.shadingNormal, n, 1e-4f, where + " shading normal");
                EXPECT_EQ(b.lightStatus, LightStatus::None) << where << " (no NEE)";
                if (k == std::size_t(scene.render.maxBounces)) {
                    EXPECT_FALSE(b.sampled) << where;
                    break;
                }
                ASSERT_TRUE(b.sampled) << where;
                EXPECT_EQ(b.lobe, 1) << where << " diffuse";
                EXPECT_EQ(b.lobeProbability, 1.0f) << where;
                const glm::vec3 albedo = scene.materials[std::size_t(s.material)].albedo;
                const float cosTheta = glm::dot(b.sampledDirection, n);
                ASSERT_GT(cosTheta, 0.0f) << where;
                EXPECT_NEAR(glm::length(b.sampledDirection), 1.0f, 1e-5f) << where;
                expectNear3(b.f, albedo / kPi, 1e-6f, where + " f = albedo/pi");
                EXPECT_NEAR(b.cosTheta, cosTheta, 1e-4f) << where;
                EXPECT_NEAR(b.pdf, cosTheta / kPi, 1e-4f) << where << " pdf = cos/pi";
                expectNear3(b.weight, albedo, 1e-6f, where + " f cos / pdf");
                beta *= glm::dvec3(b.f) * double(b.cosTheta) / double(b.pdf);
                if (int(k) + 1 >= scene.render.rrDepth) {
                    const double q = std::min(std::pow(std::max({beta.x, beta.y, beta.z}), 0.25), 0.95);
                    EXPECT_NEAR(b.rrProbability, q, 1e-5) << where;
                    ASSERT_GE(b.rrOutcome, 0) << where;
                    if (b.rrOutcome == 0) {
                        ++killed;
                        EXPECT_EQ(k + 1, p.bounces.size()) << where << ": roulette ended the path";
                        beta = glm::dvec3(0.0);
                        expectNear3(b.throughputAfter, glm::vec3(0.0f), 0.0f, where);
                        break;
                    }
                    ++survived;
                    beta /= q;
                } else {
                    EXPECT_EQ(b.rrOutcome, -1) << where;
                }
                expectNear3(b.throughputAfter, glm::vec3(beta), 1e-4f * float(glm::length(beta)), where + " throughput after");
                // The next segment starts at this hit, offset off the surface along the normal by
                // the hit point's error bound (ray.glsl offsetRayOrigin): for the ground sphere of
                // radius 100 that is about 1.3e-4, more than `scale` near the origin.
                ASSERT_LT(k + 1, p.bounces.size()) << where;
                const float offset = glm::dot(glm::abs(n), glsl::sphereHitError(s.center, s.radius));
                expectNear3(p.bounces[k + 1].origin, b.position, scale + offset, where + " next origin");
                expectNear3(p.bounces[k + 1].direction, b.sampledDirection, 1e-6f, where + " next direction");
                ++bouncesChecked;
            }
            expectNear3(p.value, glm::vec3(value), 1e-5f * float(glm::length(value) + 1.0), "path value");
        }
    }
    EXPECT_GT(bouncesChecked, 60);
    EXPECT_GT(killed + survived, 10);   // roulette was played and recorded
    expectTermsMultiplyOut(inspector.record(12, 10, 48, 0), "two spheres");
}

// The first bounce's direction is drawn from the lens pair when the camera has no lens and from
// bounce 0's own block when it has one (sampler.glsl bsdfSampleDim): the recorded direction is the
// cosine-weighted direction of that pair's numbers in the recorded shading frame, and not the
// other pair's.
TEST_F(PathInspectorTest, FirstBounceTakesTheLensPairOnlyWithoutALens) {
    for (float aperture : {0.0f, 0.05f}) {
        Scene scene = parseScene(kTwoSpheres, "two_spheres.json");
        scene.camera.aperture = aperture;
        scene.camera.focusDistance = 4.0f;
        PathInspector inspector;
        inspector.setScene(scene);
        const int x = 12, y = 10;
        int checked = 0, otherPairDiffers = 0;
        for (const PathRecord& p : inspector.record(x, y, 16, 0)) {
            ASSERT_FALSE(p.bounces.empty());
            const BounceRecord& b = p.bounces[0];
            if (!b.hit || !b.sampled) continue;
            SamplePointsQuery q;
            q.sampler = scene.render.sampler;
            q.pixel = glm::uvec2(x, scene.render.height - 1 - y);
            q.seed = scene.render.seed;
            q.spp = std::uint32_t(std::max(scene.render.spp, 1));
            q.pair = SamplePair::Bsdf;
            q.bounce = 0;
            q.first = std::uint32_t(p.sample);
            q.count = 1;
            const auto direction = [&](bool lens) {
                q.lens = lens;
                const glsl::Frame frame = glsl::frameFromNormal(b.shadingNormal);
                return glsl::frameToWorld(frame, glsl::sampleCosineHemisphere(samplePoints(q)[0]));
            };
            const std::string where = "aperture " + std::to_string(aperture) + " sample " + std::to_string(p.sample);
            expectNear3(b.sampledDirection, direction(aperture > 0.0f), 1e-4f, where);
            if (glm::length(direction(aperture == 0.0f) - b.sampledDirection) > 1e-2f) ++otherPairDiffers;
            ++checked;
        }
        EXPECT_EQ(checked, 16) << "aperture " << aperture << ": every camera ray hits and scatters";
        EXPECT_GE(otherPairDiffers, 15) << "aperture " << aperture;
    }
}

// NEE of a constant sky from one sphere: the light sample's terms, computed on the CPU.
TEST_F(PathInspectorTest, LightSampleTermsMatchACpuComputation) {
    Scene scene = parseScene(kTwoSpheres, "two_spheres.json");
    scene.spheres.erase(scene.spheres.begin());   // the ball alone: nothing occludes the sky
    scene.render.nee = true;
    PathInspector inspector;
    inspector.setScene(scene);
    int visible = 0;
    const auto paths = inspector.record(12, 9, 64, 0);
    for (const PathRecord& p : paths) {
        const BounceRecord& b = p.bounces[0];
        if (!b.hit) continue;
        const glm::vec3 albedo = scene.materials[std::size_t(b.material)].albedo;
        const float lightPdf = 1.0f / (4.0f * kPi);   // uniform sphere; the sky is the only light
        const float cosL = glm::dot(b.lightDirection, b.normal);
        EXPECT_EQ(b.lightIndex, -1);   // the sky
        EXPECT_NEAR(b.lightPdf, lightPdf, 1e-7f);
        EXPECT_LT(b.lightDistance, 0.0f);   // towards the sky
        if (cosL <= 0.0f) {
            EXPECT_EQ(b.lightStatus, LightStatus::Zero);
            continue;
        }
        ASSERT_EQ(b.lightStatus, LightStatus::Visible);
        ++visible;
        const float bsdfPdf = cosL / kPi;
        EXPECT_NEAR(b.lightBsdfPdf, bsdfPdf, 1e-5f);
        const float w = lightPdf * lightPdf / (lightPdf * lightPdf + bsdfPdf * bsdfPdf);
        EXPECT_NEAR(b.lightMisWeight, w, 1e-5f);
        const glm::vec3 expected = albedo / kPi * cosL * scene.sky.color * (w / lightPdf);
        expectNear3(b.lightContribution, expected, 1e-4f, "light contribution");
        expectNear3(b.lightRadiance, scene.sky.color, 1e-6f, "sky radiance");
    }
    EXPECT_GT(visible, 10);
    expectTermsMultiplyOut(paths, "nee sky");
}

// Recording has no side effect: the inspector's variant traces the same image, and the recorded
// values of a pixel's samples average to that pixel.
TEST_F(PathInspectorTest, InspectorVariantRendersTheSameImage) {
    for (const char* name : {"lesson_one_sphere.json", "materials.json"}) {
        const Scene scene = loadScene(scenePath(name), {"render.width=40", "render.height=24", "render.spp=4",
                                                        "render.rpp=4", "render.nee=true"});
        PathTracer normal;
        normal.setScene(scene);
        normal.renderPass(4);
        const Image a = normal.readImage();
        PathInspector inspector;
        inspector.setScene(scene);
        const auto paths = inspector.record(17, 11, 4, 0);
        // The same variant tracing the whole image, the inspected pixel among them.
        PathTracer recording(PathInspector::inspectorOptions());
        recording.setScene(scene);
        GLuint buffers[2];
        glCreateBuffers(2, buffers);
        glNamedBufferStorage(buffers[0], 4 * 64 * glsl::PR_VEC4S * 16, nullptr, 0);
        glNamedBufferStorage(buffers[1], 4 * glsl::PR_PATH_VEC4S * 16, nullptr, 0);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_INSPECT_BOUNCES, buffers[0]);
        glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_INSPECT_PATHS, buffers[1]);
        recording.program().set("uInspectPixel", glm::ivec2(17, 24 - 1 - 11));
        recording.program().set("uInspectMaxRecords", 64);
        recording.renderPass(4);
        const Image b = recording.readImage();
        glDeleteBuffers(2, buffers);
        ASSERT_EQ(a.rgba.size(), b.rgba.size());
        std::size_t differing = 0;
        for (std::size_t i = 0; i < a.rgba.size(); ++i) differing += a.rgba[i] != b.rgba[i];
        EXPECT_EQ(differing, 0u) << name;
        glm::vec3 sum(0.0f);
        for (const PathRecord& p : paths) sum += p.value;
        const glm::vec3 mean = sum / 4.0f;
        const std::size_t at = (std::size_t(11) * 40 + 17) * 4;
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(mean[c], a.rgba[at + std::size_t(c)], 1e-6f * (1.0f + mean[c])) << name;
    }
}

TEST_F(PathInspectorTest, RejectsPixelsOutsideTheImage) {
    const Scene scene = parseScene(kTwoSpheres, "two_spheres.json");
    PathInspector inspector;
    EXPECT_THROW(inspector.record(0, 0, 1), std::logic_error);
    inspector.setScene(scene);
    EXPECT_THROW(inspector.record(24, 0, 1), std::out_of_range);
    EXPECT_THROW(inspector.record(0, -1, 1), std::out_of_range);
}

TEST_F(PathInspectorTest, ExportsJsonAndCsv) {
    const Scene scene = parseScene(kTwoSpheres, "two_spheres.json");
    PathInspector inspector;
    inspector.setScene(scene);
    const auto paths = inspector.record(12, 10, 3, 0);
    const nlohmann::json j = pathsToJson(paths);
    ASSERT_EQ(j.size(), 3u);
    EXPECT_EQ(j[0]["pixel"][0], 12);
    EXPECT_EQ(j[0]["bounces"].size(), paths[0].bounces.size());
    EXPECT_TRUE(j[0]["bounces"][0].contains("bsdf_sample"));
    EXPECT_EQ(j[0]["bounces"][0]["bsdf_sample"]["lobe"], "diffuse");
    const std::string csv = pathsToCsv(paths);
    std::size_t rows = 0;
    for (const PathRecord& p : paths) rows += p.bounces.size();
    EXPECT_EQ(std::size_t(std::count(csv.begin(), csv.end(), '\n')), rows + 1);   // + the header
    // Read back: the same paths, term for term.
    const auto back = pathsFromJson(j);
    ASSERT_EQ(back.size(), paths.size());
    for (std::size_t i = 0; i < paths.size(); ++i) {
        ASSERT_EQ(back[i].bounces.size(), paths[i].bounces.size());
        EXPECT_EQ(back[i].sumOfTerms(), paths[i].sumOfTerms());
        EXPECT_EQ(back[i].bounces[0].sampledDirection, paths[i].bounces[0].sampledDirection);
        EXPECT_EQ(back[i].bounces[0].rrOutcome, paths[i].bounces[0].rrOutcome);
    }
    EXPECT_THROW(writePaths("/nonexistent/dir/x.json", paths), std::runtime_error);
    EXPECT_THROW(writePaths("x.txt", paths), std::runtime_error);
}

} // namespace
} // namespace raylab::test
