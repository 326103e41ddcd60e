// Light transport on the GPU (OSMesa): next-event estimation, BSDF sampling and MIS converge to
// the same image, with every sampler and under every estimator stage; MIS wins on the Veach scene;
// glass in a uniform environment is invisible; a GGX F = 1 sphere in a white furnace returns the
// single-scattering albedo E(μ, α), and a closed furnace Le / (1 − a), under every stage.
#include "render_helpers.h"
#include "render/light_list.h"
#include "support/batch_stats.h"
#include "shaders/include/camera.glsl"
#include "shaders/include/environment_map.glsl"
#include "support/ggx_albedo.h"
#include "support/gl_test.h"
#include "support/statistics.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

using namespace raylab;
using test::BatchStats;
using test::fractionAgreeing;
using test::renderBatches;

namespace {

// A small scene with every kind of light path: glossy plastic floor, rough gold, diffuse and
// mirror spheres, a small lamp and a gradient sky (also a light for NEE).
const char* kTransportScene = R"({
  "camera": { "position": [0, 1.6, 5], "look_at": [0, 0.5, 0], "fov": 40 },
  "render": { "width": 24, "height": 16, "rpp": 32, "spp": 128, "max_bounces": 4, "rr_depth": 2 },
  "sky": { "type": "gradient", "top": [0.3, 0.4, 0.6], "bottom": [0.2, 0.2, 0.2] },
  "materials": {
    "floor": { "albedo": 0.5, "f0": 0.04, "roughness": 0.7 },
    "gold": { "albedo": 0, "f0": [1, 0.71, 0.29], "roughness": 0.8 },
    "white": { "albedo": 0.7 },
    "mirror": { "albedo": 0, "f0": 0.9, "roughness": 0 },
    "lamp": { "albedo": 0, "emission": [1, 0.9, 0.7], "strength": 3 }
  },
  "objects": [
    { "type": "sphere", "center": [0, -100, 0], "radius": 100, "material": "floor" },
    { "type": "sphere", "center": [-1.1, 0.6, 0], "radius": 0.6, "material": "gold" },
    { "type": "sphere", "center": [0.3, 0.5, -0.6], "radius": 0.5, "material": "white" },
    { "type": "sphere", "center": [1.3, 0.4, 0.5], "radius": 0.4, "material": "mirror" },
    { "type": "sphere", "center": [0.5, 2.4, 0.5], "radius": 0.5, "material": "lamp" }
  ]
})";

Scene transportScene(std::vector<std::string> overrides) {
    return parseScene(kTransportScene, "transport.json", overrides);
}

// The transport scene with a second, dimmer and smaller lamp, so that picking lights by power and
// uniformly differ (render.light_selection).
Scene twoLampScene(std::vector<std::string> overrides) {
    Scene s = transportScene(std::move(overrides));
    Material lamp2 = *std::find_if(s.materials.begin(), s.materials.end(), [](const Material& m) { return m.name == "lamp"; });
    lamp2.name = "lamp2";
    lamp2.emissionStrength = 1.0f;
    s.materials.push_back(lamp2);
    Sphere sphere;
    sphere.center = glm::vec3(-1.6f, 1.8f, 1.2f);
    sphere.radius = 0.3f;
    sphere.material = int(s.materials.size()) - 1;
    s.spheres.push_back(sphere);
    return s;
}

// E(μ, α) of an F = 1 GGX sphere (f0 1, albedo 0) in a white furnace, seen from close up: each
// pixel against our own quadrature at its viewing cosine μ, within 0.5% on average.
void expectGgxFurnaceAlbedo(const std::vector<std::string>& extra) {
    const int w = 8, h = 8;
    for (const char* roughness : {"0.5", "1"}) {
        SCOPED_TRACE(roughness);
        std::vector<std::string> set = {"render.width=8", "render.height=8", "render.spp=2048", "render.rpp=256",
                                        "render.max_bounces=1", "camera.position=[0,0,2]", "camera.fov=40",
                                        "materials.grey.albedo=0", "materials.grey.f0=1",
                                        std::string("materials.grey.roughness=") + roughness};
        set.insert(set.end(), extra.begin(), extra.end());
        const Scene scene = loadScene(test::scenePath("furnace.json"), set);
        const Image img = test::render(scene);
        const float r = std::stof(roughness);
        const auto cam = glsl::cameraBasis(scene.camera.position, scene.camera.lookAt, scene.camera.up,
                                           scene.camera.fovY, 1.0f);
        double measured = 0.0, expected = 0.0;
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                // The pixel centre's ray (image rows are stored top first).
                const glm::vec2 ndc((float(x) + 0.5f) / float(w) * 2 - 1, 1 - (float(y) + 0.5f) / float(h) * 2);
                const glsl::Ray ray = glsl::cameraRay(cam, ndc);
                const glm::dvec3 o(ray.origin), d(glm::normalize(ray.dir));
                const double b = glm::dot(o, d), c = glm::dot(o, o) - 1.0;
                ASSERT_GT(b * b - c, 0.0) << "the sphere must fill the image";
                const glm::dvec3 n = o + (-b - std::sqrt(b * b - c)) * d;
                const double mu = -glm::dot(n, d);
                expected += test::ggxAlbedoQuadrature(mu, double(r * r), 600);
                measured += img.rgb(x, y).x;
            }
        EXPECT_NEAR(measured / (w * h), expected / (w * h), 0.005 * expected / (w * h));
    }
}

} // namespace

class LightTransportTest : public test::GlTest {};

TEST_F(LightTransportTest, NeeBsdfAndMisConvergeToTheSameImage) {
    constexpr int batches = 32;
    const BatchStats bsdf = renderBatches(transportScene({"render.nee=false"}), batches);
    const BatchStats nee = renderBatches(transportScene({"render.nee=true", "render.mis=false"}), batches);
    const BatchStats mis = renderBatches(transportScene({"render.nee=true", "render.mis=true"}), batches);
    EXPECT_GE(fractionAgreeing(mis, bsdf), 0.995);
    EXPECT_GE(fractionAgreeing(mis, nee), 0.995);
    EXPECT_GE(fractionAgreeing(nee, bsdf), 0.995);
    // The test can fail: 20% more light everywhere must be seen.
    const BatchStats brighter = renderBatches(
        transportScene({"render.nee=true", "materials.lamp.strength=3.6", "sky.strength=1.2"}), batches);
    EXPECT_LT(fractionAgreeing(mis, brighter), 0.9);
}

TEST_F(LightTransportTest, EverySamplerConvergesToTheSameImage) {
    // Stratified and sobol use the same dimensions in every strategy: BSDF-only and NEE with MIS
    // under each must agree with independent BSDF sampling, pixel by pixel (batches are seeds, so
    // their means are independent whatever the sampler).
    constexpr int batches = 32;
    const BatchStats reference = renderBatches(transportScene({"render.nee=false"}), batches);
    for (const char* sampler : {"stratified", "sobol", "zsobol"}) {
        const std::string set = std::string("render.sampler=") + sampler;
        const BatchStats bsdf = renderBatches(transportScene({"render.nee=false", set}), batches);
        const BatchStats mis = renderBatches(transportScene({"render.nee=true", "render.mis=true", set}), batches);
        EXPECT_GE(fractionAgreeing(bsdf, reference), 0.995) << sampler;
        EXPECT_GE(fractionAgreeing(mis, reference), 0.995) << sampler;
    }
}

TEST_F(LightTransportTest, NeeBsdfAndMisAgreeUnderAnImportanceSampledSkyMap) {
    // The transport scene lit by a sky image instead of the gradient, lamp off: NEE samples the
    // map by its piecewise-constant distribution. The map (written here) has a broad bright
    // "sun" (20 degrees, 8× the sky) and a black ground half, so every strategy has tails mild
    // enough for per-pixel z-tests, and black texels are exercised.
    constexpr int batches = 32;
    const std::filesystem::path map = std::filesystem::temp_directory_path() / "raylab_transport_sky.exr";
    {
        const int w = 64, h = 32;
        std::vector<float> px;
        const glm::vec3 sun = glm::normalize(glm::vec3(0.5f, 0.8f, -0.3f));
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const glm::vec3 d = glsl::directionFromEquirect(glm::vec2((float(x) + 0.5f) / w, (float(y) + 0.5f) / h), 0.0f);
                glm::vec3 c = d.y < 0.0f ? glm::vec3(0.0f) : glm::vec3(0.3f, 0.4f, 0.6f);
                if (glm::dot(d, sun) > std::cos(glm::radians(20.0f))) c = glm::vec3(3.0f, 2.6f, 2.0f);
                px.insert(px.end(), {c.r, c.g, c.b});
            }
        auto out = OIIO::ImageOutput::create(map.string());
        ASSERT_TRUE(out && out->open(map.string(), OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT)) &&
                    out->write_image(OIIO::TypeDesc::FLOAT, px.data()) && out->close());
    }
    const std::vector<std::string> sky = {"sky.type=map", "sky.map=\"" + map.string() + "\"", "sky.rotation=40",
                                          "materials.lamp.strength=0"};
    auto with = [&](std::vector<std::string> more) {
        more.insert(more.end(), sky.begin(), sky.end());
        return transportScene(more);
    };
    const BatchStats bsdf = renderBatches(with({"render.nee=false"}), batches);
    const BatchStats nee = renderBatches(with({"render.nee=true", "render.mis=false"}), batches);
    const BatchStats mis = renderBatches(with({"render.nee=true", "render.mis=true"}), batches);
    EXPECT_GE(fractionAgreeing(mis, bsdf), 0.995);
    EXPECT_GE(fractionAgreeing(mis, nee), 0.995);
    EXPECT_GE(fractionAgreeing(nee, bsdf), 0.995);
}

TEST_F(LightTransportTest, MisHasLowerErrorThanEitherStrategyOnTheVeachScene) {
    // Equal samples per pixel; the reference is MIS at 64× the samples. RMSE printed for
    // bench/materials.md.
    const std::vector<std::string> size = {"render.width=64", "render.height=32", "render.rpp=16"};
    auto with = [&](std::vector<std::string> more) {
        more.insert(more.end(), size.begin(), size.end());
        return loadScene(test::scenePath("veach_mis.json"), more);
    };
    const Image reference = test::render(with({"render.spp=1024", "render.seed=99"}));
    const double bsdf = test::rmse(test::render(with({"render.spp=16", "render.nee=false"})), reference);
    const double nee = test::rmse(test::render(with({"render.spp=16", "render.mis=false"})), reference);
    const double mis = test::rmse(test::render(with({"render.spp=16"})), reference);
    std::printf("veach_mis 64x32, 16 spp, RMSE vs 1024 spp MIS: BSDF only %.4f, NEE only %.4f, MIS %.4f\n", bsdf,
                nee, mis);
    EXPECT_LT(mis, bsdf);
    EXPECT_LT(mis, nee);
}

TEST_F(LightTransportTest, SmoothGlassSphereInAUniformEnvironmentIsInvisible) {
    // furnace.json's sphere made of glass: every path leaves the sphere again with weight
    // (1/η²)·η² = 1, so every pixel is the sky's radiance 1, whatever the IOR.
    for (const char* ior : {"1.5", "0.6666667", "1.33", "1"}) {
        SCOPED_TRACE(ior);
        const Scene scene = loadScene(test::scenePath("furnace.json"),
                                      {"render.width=16", "render.height=16", "render.max_bounces=64",
                                       "materials.grey.transmission=1", "materials.grey.roughness=0",
                                       std::string("materials.grey.ior=") + ior});
        const Image img = test::render(scene);
        for (size_t i = 0; i < img.rgba.size(); ++i)
            if (i % 4 != 3) {
                ASSERT_NEAR(img.rgba[i], 1.0f, 1e-4f) << "pixel " << i / 4;
            }
    }
}

TEST_F(LightTransportTest, GgxFurnaceReturnsTheSingleScatteringAlbedo) { expectGgxFurnaceAlbedo({}); }

TEST_F(LightTransportTest, MaterialScenesProduceNoNanInAnyLightSamplingMode) {
    // Every material of the sweep (mirror, smooth and rough glass, metals, plastics) with NEE and
    // MIS on and off: no sample may be NaN or Inf.
    for (const char* scene : {"materials.json", "veach_mis.json"})
        for (const char* mode : {"render.nee=false", "render.mis=false", "render.mis=true"}) {
            SCOPED_TRACE(std::string(scene) + " " + mode);
            const Scene s = loadScene(test::scenePath(scene), {"render.width=40", "render.height=16", "render.spp=16",
                                                               "render.rpp=16", "render.nee=true", mode});
            PathTracer tracer;
            tracer.setScene(s);
            renderProgressively(tracer, s.render);
            EXPECT_EQ(tracer.nonFiniteSamples(), 0u);
        }
}

// Every estimator stage at its value other than the default (the default estimator is the tests
// above) is unbiased: it only changes the noise or the cost.
class EstimatorStageTest : public test::GlTest, public ::testing::WithParamInterface<const char*> {};

// "render.accel=boxes" names the test accel_boxes.
std::string stageTestName(const ::testing::TestParamInfo<const char*>& p) {
    std::string name = std::string(p.param).substr(7);
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

TEST_P(EstimatorStageTest, BsdfNeeAndMisAgreeWithTheDefaultEstimator) {
    constexpr int batches = 32;
    ASSERT_TRUE(lightPowersDiffer(twoLampScene({}))) << "light_selection must have something to choose";
    static const BatchStats reference = renderBatches(twoLampScene({}), batches);
    const std::string stage = GetParam();
    const BatchStats bsdf = renderBatches(twoLampScene({"render.nee=false", stage}), batches);
    const BatchStats nee = renderBatches(twoLampScene({"render.mis=false", stage}), batches);
    const BatchStats mis = renderBatches(twoLampScene({stage}), batches);
    EXPECT_GE(fractionAgreeing(bsdf, reference), 0.995);
    EXPECT_GE(fractionAgreeing(nee, reference), 0.995);
    EXPECT_GE(fractionAgreeing(mis, reference), 0.995);
}

TEST_P(EstimatorStageTest, ClosedFurnaceConvergesToEmissionOverOneMinusAlbedo) {
    const Scene scene = loadScene(test::scenePath("closed_furnace.json"), {GetParam()});
    const Material& m = scene.materials[size_t(scene.spheres.at(0).material)];
    const Image image = test::render(scene);
    for (int c = 0; c < 3; ++c) {
        const double expected = m.radiance()[c] / (1.0 - m.albedo[c]);
        const auto values = test::channel(image, c);
        const double se = test::standardError(values);
        EXPECT_NEAR(test::mean(values), expected, 3.0 * se) << "channel " << c;
        EXPECT_LT(se, 0.01 * expected) << "too noisy to mean anything";
    }
}

TEST_P(EstimatorStageTest, GgxFurnaceReturnsTheSingleScatteringAlbedo) { expectGgxFurnaceAlbedo({GetParam()}); }

INSTANTIATE_TEST_SUITE_P(EveryOtherValue, EstimatorStageTest,
                         ::testing::Values("render.diffuse_sampling=uniform", "render.ggx_sampling=d_cos",
                                           "render.light_selection=uniform", "render.accel=boxes",
                                           "render.accel=none"),
                         stageTestName);
