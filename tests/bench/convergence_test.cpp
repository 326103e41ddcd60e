// The pieces of the run-time-against-error benchmark: metrics, interpolation, reference cache,
// Blender export, and the convergence subcommand end to end on a tiny suite.
#include "bench/blender_export.h"
#include "bench/convergence.h"
#include "bench/error_metrics.h"
#include "bench/reference.h"
#include "io/image_io.h"
#include "gl/gl_context.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <regex>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

fs::path scratch() {
    fs::path d = fs::temp_directory_path() / ("raylab_bench_unit_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}

Image constant(int w, int h, float v) {
    Image im(w, h);
    for (size_t i = 0; i < im.rgba.size(); ++i) im.rgba[i] = i % 4 == 3 ? 1.0f : v;
    return im;
}

// Checkpoints at 1, 2, 4 … maxSpp with RMSE = scale/sqrt(spp) and secondsPerSpp per sample.
std::vector<Checkpoint> sqrtCurve(std::uint64_t maxSpp, double secondsPerSpp, double scale = 1.0) {
    std::vector<Checkpoint> c;
    for (std::uint64_t spp = 1; spp <= maxSpp; spp *= 2) {
        Checkpoint p;
        p.spp = spp;
        p.seconds = double(spp) * secondsPerSpp;
        p.error.rmse = scale / std::sqrt(double(spp));
        c.push_back(p);
    }
    return c;
}

} // namespace

TEST(BenchErrorMetrics, MseRmseAndRelMse) {
    const Image ref = constant(4, 2, 1.0f);
    const Image img = constant(4, 2, 1.5f);
    const ImageError e = imageError(img, ref);
    EXPECT_DOUBLE_EQ(e.mse, 0.25);
    EXPECT_DOUBLE_EQ(e.rmse, 0.5);
    EXPECT_NEAR(e.relMse, 0.25 / 1.01, 1e-12);   // (I−R)² / (R² + 0.01)
    EXPECT_DOUBLE_EQ(imageMean(img), 1.5);
    EXPECT_THROW(imageError(constant(2, 2, 0.0f), ref), std::invalid_argument);
}

TEST(BenchConvergence, TimeToReachInterpolatesLogLogAndSlopeIsMinusHalf) {
    // RMSE = 1/sqrt(spp), time = spp ms: RMSE 0.1 is reached at 100 spp = 0.1 s exactly on the
    // log–log line between the checkpoints 64 and 128.
    std::vector<Checkpoint> curve;
    for (std::uint64_t spp = 1; spp <= 1024; spp *= 2) {
        Checkpoint c;
        c.spp = spp;
        c.seconds = double(spp) * 1e-3;
        c.error.rmse = 1.0 / std::sqrt(double(spp));
        c.error.mse = c.error.rmse * c.error.rmse;
        curve.push_back(c);
    }
    EXPECT_NEAR(timeToReach(curve, 0.1), 0.1, 1e-9);
    EXPECT_LT(timeToReach(curve, 0.001), 0.0);   // never reached
    EXPECT_NEAR(convergenceSlope(curve), -0.5, 1e-9);
    // Exact checkpoints (RMSE 0) have no logarithm: the fit leaves them out instead of giving NaN.
    curve[0].error.rmse = curve[1].error.rmse = 0.0;
    EXPECT_NEAR(convergenceSlope(curve), -0.5, 1e-9);
    EXPECT_NEAR(efficiency(curve.back()), 1.0 / (curve.back().error.mse * 1.024), 1e-9);
}

TEST(BenchConvergence, TimeToReachTakesTheCheapestRunThatGetsThere) {
    // A peer's checkpoints are separate runs: here the 1-spp run took 1.5 s (a slow start) and
    // the 4-spp run 0.8 s. RMSE 0.6 is first crossed between 1 and 2 spp (≈1.2 s interpolated),
    // but the 4-spp run reached it in 0.8 s: the least time is the answer, never more time for a
    // looser target.
    const double rmse[] = {1.0, 0.5, 0.25};
    const double seconds[] = {1.5, 1.0, 0.8};
    std::vector<Checkpoint> curve;
    for (int i = 0; i < 3; ++i) {
        Checkpoint c;
        c.spp = std::uint64_t(1) << (2 * i);
        c.seconds = seconds[i];
        c.error.rmse = rmse[i];
        curve.push_back(c);
    }
    EXPECT_NEAR(timeToReach(curve, 0.6), 0.8, 1e-12);
    EXPECT_NEAR(timeToReach(curve, 0.25), 0.8, 1e-12);
    EXPECT_LE(timeToReach(curve, 0.6), timeToReach(curve, 0.25));
}

TEST(BenchConvergence, MeanOverSeedsAveragesMseNotRmse) {
    // Two seeds at RMSE 1/√spp and 3/√spp: the mean MSE is 5/spp, so the RMSE is √5/√spp (the mean
    // of the RMSEs, 2/√spp, would understate it) and the slope stays −0.5; times are averaged.
    std::vector<std::vector<Checkpoint>> seeds = {sqrtCurve(64, 0.01, 1.0), sqrtCurve(64, 0.03, 3.0)};
    for (auto& c : seeds)
        for (Checkpoint& p : c) p.error.mse = p.error.rmse * p.error.rmse;
    const std::vector<Checkpoint> mean = meanOverSeeds(seeds);
    ASSERT_EQ(mean.size(), seeds[0].size());
    for (const Checkpoint& p : mean) {
        EXPECT_NEAR(p.error.mse, 5.0 / double(p.spp), 1e-12);
        EXPECT_NEAR(p.error.rmse, std::sqrt(5.0 / double(p.spp)), 1e-12);
        EXPECT_NEAR(p.seconds, 0.02 * double(p.spp), 1e-12);
    }
    EXPECT_NEAR(convergenceSlope(mean), -0.5, 1e-9);
    // A lone seed is its own mean; curves that do not share their checkpoints cannot be averaged.
    const std::vector<Checkpoint> one = meanOverSeeds(std::span(seeds).first(1));
    EXPECT_NEAR(one.back().error.rmse, seeds[0].back().error.rmse, 1e-12);
    seeds[1].pop_back();
    EXPECT_THROW(meanOverSeeds(seeds), std::invalid_argument);
    seeds[1] = sqrtCurve(64, 0.03, 3.0);
    seeds[1][2].spp = 5;
    EXPECT_THROW(meanOverSeeds(seeds), std::invalid_argument);
}

TEST(BenchConvergence, TimeToErrorGoalIsARatioWhenBothReachAndABoundOtherwise) {
    // raylab: RMSE = 1/sqrt(spp) at 1 ms per spp up to 1024 spp, 0.05 s start-up. Peer: the same
    // RMSE at 10 ms per spp up to 64 spp (separate runs).
    using V = TimeToErrorGoal::Verdict;
    using B = TimeToErrorGoal::Bound;
    const auto raylab = sqrtCurve(1024, 1e-3), peer = sqrtCurve(64, 1e-2);
    // Both reach RMSE 0.25 at 16 spp: peer 0.16 s, raylab 0.016 + 0.05 s (start-up counts).
    TimeToErrorGoal g = timeToErrorGoal(raylab, 0.05, peer, 0.25, 0.25, 3.0);
    EXPECT_EQ(g.bound, B::Exact);
    EXPECT_NEAR(g.raylabSeconds, 0.066, 1e-9);
    EXPECT_NEAR(g.ratio, 0.16 / 0.066, 1e-9);
    EXPECT_EQ(g.verdict, V::NotMet);
    EXPECT_EQ(timeToErrorGoal(raylab, 0.0, peer, 0.25, 0.25, 3.0).verdict, V::Met);   // 10× without it
    // Only raylab reaches RMSE 1/32 (1024 spp, 1.024 + 0.05 s); the peer's longest run took 0.64 s:
    // the ratio is at least 0.64 / 1.074, which does not decide a goal of 3, but decides 0.5.
    g = timeToErrorGoal(raylab, 0.05, peer, 1.0 / 32.0, 1.0 / 32.0, 3.0);
    EXPECT_EQ(g.bound, B::AtLeast);
    EXPECT_LT(g.peerSeconds, 0.0);
    EXPECT_NEAR(g.ratio, 0.64 / 1.074, 1e-9);
    EXPECT_EQ(g.verdict, V::Open);
    EXPECT_EQ(timeToErrorGoal(raylab, 0.05, peer, 1.0 / 32.0, 1.0 / 32.0, 0.5).verdict, V::Met);
    // Only the peer reaches RMSE 1/8 (64 spp, 0.64 s) where raylab stops at 16 spp (0.016 + 0.05
    // s): raylab's time is later, so the ratio is at most 0.64 / 0.066 — below a goal of 20.
    const auto shortRaylab = sqrtCurve(16, 1e-3);
    g = timeToErrorGoal(shortRaylab, 0.05, peer, 1.0 / 8.0, 1.0 / 8.0, 20.0);
    EXPECT_EQ(g.bound, B::AtMost);
    EXPECT_NEAR(g.ratio, 0.64 / 0.066, 1e-9);
    EXPECT_EQ(g.verdict, V::NotMet);
    EXPECT_EQ(timeToErrorGoal(shortRaylab, 0.05, peer, 1.0 / 8.0, 1.0 / 8.0, 3.0).verdict, V::Open);
    // Neither reaches it: nothing is decided.
    g = timeToErrorGoal(shortRaylab, 0.05, peer, 0.01, 0.01, 3.0);
    EXPECT_EQ(g.bound, B::None);
    EXPECT_EQ(g.verdict, V::Open);
}

TEST(BenchConvergence, TheGoalTakesThePeersFastestCurveAndAMissedLevelCountsItsLongestRun) {
    // raylab: RMSE = 1/sqrt(spp), 1 ms per spp, no start-up. Peer curves (Cycles without and with
    // adaptive sampling): 10 ms per spp to 64 spp, 5 ms per spp to 16 spp, 20 ms per spp to 64.
    using B = TimeToErrorGoal::Bound;
    const auto raylab = sqrtCurve(1024, 1e-3);
    const std::vector<std::vector<Checkpoint>> peers = {sqrtCurve(64, 1e-2), sqrtCurve(16, 5e-3),
                                                        sqrtCurve(64, 2e-2)};
    // RMSE 1/4 (16 spp): all three reach it; the second is fastest (0.08 s against 0.016).
    size_t which = 99;
    TimeToErrorGoal g = timeToErrorGoalAgainstFastest(raylab, 0.0, peers, 0.25, 0.25, 3.0, &which);
    EXPECT_EQ(which, 1u);
    EXPECT_EQ(g.bound, B::Exact);
    EXPECT_NEAR(g.ratio, 0.08 / 0.016, 1e-9);
    // RMSE 1/8 (64 spp): the second misses it, its longest run (16 spp, 0.08 s) a lower bound below
    // the first's 0.64 s, so the ratio is only a bound against it: never flattered by the slower curve.
    g = timeToErrorGoalAgainstFastest(raylab, 0.0, peers, 0.125, 0.125, 3.0, &which);
    EXPECT_EQ(which, 1u);
    EXPECT_EQ(g.bound, B::AtLeast);
    EXPECT_NEAR(g.ratio, 0.08 / 0.064, 1e-9);
    // Without the second, the first is fastest and the ratio exact; one curve is its own fastest.
    const std::vector<std::vector<Checkpoint>> two = {peers[2], peers[0]};
    g = timeToErrorGoalAgainstFastest(raylab, 0.0, two, 0.125, 0.125, 3.0, &which);
    EXPECT_EQ(which, 1u);
    EXPECT_EQ(g.bound, B::Exact);
    EXPECT_NEAR(g.ratio, 0.64 / 0.064, 1e-9);
    const TimeToErrorGoal alone = timeToErrorGoalAgainstFastest(raylab, 0.05, std::span(peers).first(1), 0.25, 0.25, 3.0);
    const TimeToErrorGoal direct = timeToErrorGoal(raylab, 0.05, peers[0], 0.25, 0.25, 3.0);
    EXPECT_EQ(alone.ratio, direct.ratio);
    EXPECT_EQ(alone.verdict, direct.verdict);
    EXPECT_THROW(timeToErrorGoalAgainstFastest(raylab, 0.0, {}, 0.25, 0.25, 3.0), std::invalid_argument);
}

TEST(BenchConvergence, TheCostPerSampleComesFromTheEvenCurveWhereThereIsOne) {
    const std::vector<std::string> withEven{"raylab", "raylab:bsdf", "raylab:even", "cycles"};
    EXPECT_EQ(tracerCostCurve(withEven), 2u);
    const std::vector<std::string> without{"raylab", "raylab:mis", "cycles", "cycles:adaptive"};
    EXPECT_EQ(tracerCostCurve(without), 0u);
}

TEST(BenchConvergence, PeerCurveGoesOnOnlyWhereRaylabReachedALevelThePeerHasNotAndNoBoundDecidesIt) {
    // RMSE = scale/sqrt(spp) against a mean of 1; levels 5 % and 2 %.
    const double levels[] = {0.05, 0.02};
    const auto raylab = sqrtCurve(1024, 1e-3, 0.5);   // 5 % at 100 spp, 2 % at 625 spp: both reached
    EXPECT_TRUE(peerCurveUndecided(raylab, sqrtCurve(64, 1e-3, 0.5), levels, 1.0, 1.0, 0.0, 3.0));     // peer: neither yet
    EXPECT_TRUE(peerCurveUndecided(raylab, sqrtCurve(256, 1e-3, 0.5), levels, 1.0, 1.0, 0.0, 3.0));    // peer: 5 % only
    EXPECT_FALSE(peerCurveUndecided(raylab, sqrtCurve(1024, 1e-3, 0.5), levels, 1.0, 1.0, 0.0, 3.0));  // peer: both
    // raylab reached neither: more peer samples could not give a ratio.
    EXPECT_FALSE(peerCurveUndecided(sqrtCurve(64, 1e-3, 0.5), sqrtCurve(64, 1e-3, 0.5), levels, 1.0, 1.0, 0.0, 3.0));
    // Each renderer's level is of its own reference's mean: a peer mean twice as large halves
    // the peer's relative error, so its 64 spp already reach 5 %, not 2 %.
    EXPECT_TRUE(peerCurveUndecided(raylab, sqrtCurve(64, 1e-3, 0.5), levels, 1.0, 2.0, 0.0, 3.0));
    EXPECT_FALSE(peerCurveUndecided(raylab, sqrtCurve(256, 1e-3, 0.5), levels, 1.0, 2.0, 0.0, 3.0));
    // A peer slower than the goal's ratio in its longest run already decides the goal by its
    // bound: raylab reaches 2 % at 0.625 s, the peer's 256 spp (5 % only) took 2.56 s > 3 × 0.625.
    EXPECT_FALSE(peerCurveUndecided(raylab, sqrtCurve(256, 1e-2, 0.5), levels, 1.0, 1.0, 0.0, 3.0));
    // raylab's start-up counts: with 0.5 s of it, 3 × 1.125 s is more than the peer's 2.56 s.
    EXPECT_TRUE(peerCurveUndecided(raylab, sqrtCurve(256, 1e-2, 0.5), levels, 1.0, 1.0, 0.5, 3.0));
    // At a goal of 4.5 the same run is not enough either, nor at a goal no bound reaches.
    EXPECT_TRUE(peerCurveUndecided(raylab, sqrtCurve(256, 1e-2, 0.5), levels, 1.0, 1.0, 0.0, 4.5));
    EXPECT_TRUE(peerCurveUndecided(raylab, sqrtCurve(256, 1e-2, 0.5), levels, 1.0, 1.0, 0.0,
                                   std::numeric_limits<double>::infinity()));
}

TEST(BenchConvergence, RaylabCurveGoesOnWhileItMissesAGoalLevel) {
    // RMSE = 0.5/sqrt(spp) against a mean of 1: 5 % at 100 spp, 2 % at 625 spp.
    const double levels[] = {0.05, 0.02};
    EXPECT_TRUE(curveMissesALevel(sqrtCurve(64, 1e-3, 0.5), levels, 1.0));     // neither
    EXPECT_TRUE(curveMissesALevel(sqrtCurve(256, 1e-3, 0.5), levels, 1.0));    // 5 % only
    EXPECT_FALSE(curveMissesALevel(sqrtCurve(1024, 1e-3, 0.5), levels, 1.0));  // both
    // The levels are of the reference's mean: twice the mean halves the relative error.
    EXPECT_FALSE(curveMissesALevel(sqrtCurve(256, 1e-3, 0.5), levels, 2.0));
}

TEST(BenchReference, CachedReferenceIsReusedAndRebuiltWhenItsKeyChanges) {
    const fs::path base = scratch() / "ref";
    fs::remove(base.string() + ".json");
    int calls = 0;
    auto batch = [&](int k) {
        ++calls;
        return constant(3, 2, float(k));   // batches 0, 1, 2, 3: mean 1.5, sample variance 5/3
    };
    Reference a = cachedReference(base, "key-1", 4, batch, "desc", "cmd");
    EXPECT_EQ(calls, 4);
    EXPECT_FALSE(a.fromCache);
    EXPECT_NEAR(a.mean.rgba[0], 1.5f, 1e-6f);
    EXPECT_NEAR(a.variance.rgba[0], (5.0f / 3.0f) / 4.0f, 1e-6f);   // variance of the mean
    Reference b = cachedReference(base, "key-1", 4, batch, "desc", "cmd");
    EXPECT_EQ(calls, 4) << "the cache was not used";
    EXPECT_TRUE(b.fromCache);
    EXPECT_EQ(b.mean.rgba, a.mean.rgba);
    EXPECT_EQ(b.command, "cmd");
    cachedReference(base, "key-2", 4, batch, "desc", "cmd");
    EXPECT_EQ(calls, 8) << "a changed key must rebuild the reference";
}

TEST(BenchBlenderExport, ScriptRebuildsTheSceneInBlenderCoordinatesAndIsValidPython) {
    Scene scene = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/default.json");
    scene.materials[0].name = "quote\"and\\back";
    const std::string py = blenderScript(scene);
    // y-up (6, 3.2, 8) becomes z-up (6, -8, 3.2).
    EXPECT_NE(py.find("camera((6, -8, 3.2), (0, -0, 0.8), (0, -0, 1), 32)"), std::string::npos) << py;
    EXPECT_NE(py.find("sphere(\"sphere0\", (0, -0, -1000), 1000, mat"), std::string::npos);
    EXPECT_NE(py.find("world_gradient("), std::string::npos);
    EXPECT_NE(py.find("settings(640, 360, 7, 1)"), std::string::npos) << "Cycles counts the bounces after the first";
    EXPECT_NE(py.find("material(\"quote\\\"and\\\\back\""), std::string::npos);
    // No far plane short of the scene: Blender's default (100 units) hid the Cornell box (mm).
    EXPECT_NE(py.find("data.clip_end = 1e9"), std::string::npos);
    const fs::path file = scratch() / "scene.py";
    writeBlenderScript(scene, file);
    const std::string cmd = "python3 -c \"import ast,sys; ast.parse(open(sys.argv[1]).read())\" '" + file.string() + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << "the exported script is not valid Python";
}

TEST(BenchBlenderExport, TheRenderDriverTurnsOnCyclesAdaptiveSamplingOnlyWhenAsked) {
    // The script's render_if_asked, run under python3 against a stand-in for Blender's scene: the
    // settings it leaves for each command line (Blender itself is not needed by the tests).
    const fs::path file = scratch() / "driver.py";
    writeBlenderScript(loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/default.json"), file);
    const fs::path probe = scratch() / "driver_probe.py";
    std::ofstream(probe) << R"(import ast, sys, time, types
tree = ast.parse(open(sys.argv[1]).read())
driver = next(f for f in tree.body if isinstance(f, ast.FunctionDef) and f.name == "render_if_asked")
scene = types.SimpleNamespace(cycles=types.SimpleNamespace(use_adaptive_sampling=False, adaptive_threshold=0.01,
                              adaptive_min_samples=7), render=types.SimpleNamespace())
bpy = types.SimpleNamespace(context=types.SimpleNamespace(scene=scene),
                            ops=types.SimpleNamespace(render=types.SimpleNamespace(render=lambda **k: None)))
space = {"bpy": bpy, "sys": sys, "time": time}
exec(compile(ast.Module(body=[driver], type_ignores=[]), "driver", "exec"), space)
sys.argv = ["blender", "--", "--samples", "32", "--threads", "2", "--seed", "5"] + sys.argv[2:] + ["--output", "x.exr"]
space["render_if_asked"]()
c = scene.cycles
print("samples", c.samples, "adaptive", c.use_adaptive_sampling, c.adaptive_threshold, c.adaptive_min_samples)
)";
    const auto run = [&](const std::string& extra) {
        const std::string cmd = "python3 '" + probe.string() + "' '" + file.string() + "' " + extra + " 2>&1";
        std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
        std::string out;
        for (int c; (c = std::fgetc(pipe.get())) != EOF;) out += char(c);
        return out;
    };
    // Off unless asked (the "cycles" curve is the even one); asked, on at the given noise threshold
    // (0: Cycles sets it from the sample count) with the minimum of samples left to Cycles.
    EXPECT_NE(run("").find("samples 32 adaptive False 0.01 7"), std::string::npos) << run("");
    EXPECT_NE(run("--adaptive-threshold 0.02").find("samples 32 adaptive True 0.02 0"), std::string::npos)
        << run("--adaptive-threshold 0.02");
    EXPECT_NE(run("--adaptive-threshold 0").find("samples 32 adaptive True 0.0 0"), std::string::npos)
        << run("--adaptive-threshold 0");
}

TEST(BenchBlenderExport, TheSceneTextLeavesOutTheDriverAlone) {
    // Cycles' cached references are keyed by the script without its driver, so a change to how
    // runs are driven keeps them: the scene text is the whole script up to the driver, which ends it.
    const std::string script = blenderScript(loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/cornell_box.json"));
    const std::string scene = blenderSceneText(script);
    EXPECT_LT(scene.size(), script.size());
    EXPECT_EQ(script.rfind(scene, 0), 0u);
    EXPECT_EQ(scene.find("render_if_asked"), std::string::npos);
    EXPECT_NE(script.find("def render_if_asked", scene.size()), std::string::npos);
    EXPECT_NE(scene.find("camera("), std::string::npos) << "the scene itself stays in the key";
    // Text that does not end with the driver is kept whole.
    EXPECT_EQ(blenderSceneText(scene + "x"), scene + "x");
}

TEST(BenchBlenderExport, PointSpotAndDistantLightsBecomePointSpotAndSun) {
    // Point: power 4πI; spot: the same, spot_size 2·outer, blend (cos inner − cos outer)/(1 − cos
    // outer); distant: SUN of angle 2·radius and strength E(1 + 1/cos radius)/2 (a facing surface
    // receives E), shining along its direction (z-up).
    Scene scene = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/default.json");
    Light point, spot, sun;
    point.position = glm::vec3(1, 2, 3);
    point.intensity = glm::vec3(2, 1, 0.5f);
    spot.type = Light::Type::Spot;
    spot.position = glm::vec3(0, 4, 0);
    spot.power = float(4.0 * 3.14159265358979);
    spot.innerAngle = 20.0f;
    spot.outerAngle = 30.0f;
    sun.type = Light::Type::Distant;
    sun.direction = glm::vec3(0, -1, -1);
    sun.irradiance = glm::vec3(3.0f);
    sun.angularRadius = 0.5f;
    scene.lights = {point, spot, sun};
    const std::string py = blenderScript(scene);
    EXPECT_NE(py.find("light(\"light0\", \"POINT\", (1, -3, 2), (0, 0, -1), (1, 0.5, 0.25, 1.0), 25.13274)"),
              std::string::npos) << py;
    const double co = std::cos(glm::radians(30.0)), ci = std::cos(glm::radians(20.0));
    char spotText[200];
    std::snprintf(spotText, sizeof spotText, "\"SPOT\", (0, -0, 4), (0, -0, -1), (1, 1, 1, 1.0), %.7g, spot_size=1.047198, spot_blend=%.7g)",
                  4.0 * 3.14159265358979 * double(spot.power) / (2.0 * 3.14159265358979 * (1.0 - 0.5 * (ci + co))),
                  (ci - co) / (1.0 - co));
    EXPECT_NE(py.find(spotText), std::string::npos) << spotText << "\n" << py;
    EXPECT_NE(py.find("light(\"light2\", \"SUN\", (0, 0, 0), (0, 1, -1), (1, 1, 1, 1.0), 3.000057, angle=0.01745329)"),
              std::string::npos) << py;
}

TEST(BenchBlenderExport, NamesWhatItCanOnlyApproximate) {
    const auto load = [](const char* name) { return loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/" + name); };
    EXPECT_TRUE(blenderExportApproximations(load("default.json")).empty()) << "Lambert and emission map exactly";
    EXPECT_TRUE(blenderExportApproximations(load("cornell_box.json")).empty());
    const auto materials = blenderExportApproximations(load("materials.json"));
    ASSERT_EQ(materials.size(), 1u);
    EXPECT_NE(materials[0].find("Fresnel"), std::string::npos) << materials[0];
    const auto textured = blenderExportApproximations(load("textured_bricks.json"));
    ASSERT_EQ(textured.size(), 3u);
    EXPECT_NE(textured[1].find("mip"), std::string::npos) << textured[1];
    EXPECT_NE(textured[2].find("normal maps"), std::string::npos) << textured[2];
    Scene mirror = load("default.json");
    mirror.materials[1].f0 = glm::vec3(0.9f);   // a smooth coloured mirror: F is taken at h = n
    mirror.materials[1].roughness = 0.0f;
    EXPECT_TRUE(blenderExportApproximations(mirror).empty());
    mirror.materials[1].roughness = 0.3f;
    EXPECT_FALSE(blenderExportApproximations(mirror).empty());
}

namespace {

// The line of the script that makes material `name`.
std::string materialLine(const std::string& py, const std::string& name) {
    const auto at = py.find("= material(\"" + name + "\"");
    if (at == std::string::npos) return "";
    return py.substr(at, py.find('\n', at) - at);
}

} // namespace

TEST(BenchBlenderExport, PlasticsAndMetalsAreLambertUnderAHalfVectorFresnelGgxLobe) {
    const Scene scene = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/materials.json");
    const std::string py = blenderScript(scene);
    auto has = [&](const std::string& s) { EXPECT_NE(py.find(s), std::string::npos) << s; };
    // The values: raylab's albedo, f0 and perceptual roughness as they are.
    EXPECT_EQ(materialLine(py, "plastic_rough"),
              "= material(\"plastic_rough\", (0.75, 0.1, 0.08, 1.0), (0, 0, 0, 1.0), f0=(0.04, 0.04, 0.04, 1.0), "
              "roughness=0.7, transmission=0, ior=1.5)");
    EXPECT_EQ(materialLine(py, "gold_polished"),
              "= material(\"gold_polished\", (0, 0, 0, 1.0), (0, 0, 0, 1.0), f0=(1, 0.71, 0.29, 1.0), "
              "roughness=0.15, transmission=0, ior=1.5)");
    // The node setup: the GGX lobe is a Principled BSDF with metallic 1 and base colour f0 (its
    // Fresnel is at the half vector), single-scattering GGX, nothing else of the Principled on;
    // the diffuse lobe is Lambert weighted by 1 - Schlick F at the view angle.
    has("gloss = bent(tree.nodes.new(\"ShaderNodeBsdfPrincipled\"))");
    has("gloss.distribution = \"GGX\"");
    has("feed(tree, gloss.inputs[\"Base Color\"], f0)");
    has("gloss.inputs[\"Metallic\"].default_value = 1.0");
    has("gloss.inputs[\"Specular\"].default_value = 0.5");
    has("gloss.inputs[\"Specular Tint\"].default_value = 0.0");
    has("gloss.inputs[\"Sheen\"].default_value = 0.0");
    has("gloss.inputs[\"Clearcoat\"].default_value = 0.0");
    has("feed(tree, gloss.inputs[\"Roughness\"], roughness)");
    has("diffuse.inputs[\"Roughness\"].default_value = 0.0   # Lambert");
    has("facing.inputs[\"Blend\"].default_value = 0.5");
    has("pow5 = smath(tree, \"POWER\", facing.outputs[\"Facing\"], 5.0)");
    has("weight = vmath(tree, \"SUBTRACT\", 1.0, fresnel.outputs[0])");
    EXPECT_EQ(py.find("ShaderNodeBsdfGlossy"), std::string::npos) << "Glossy BSDF has no Fresnel of its own";
    EXPECT_EQ(py.find("MULTI_GGX"), std::string::npos);
}

TEST(BenchBlenderExport, TexturesAreNamedByAbsolutePathsWithRaylabsDecodingAndWrap) {
    // Loaded through a relative path from another working directory: the script must name the
    // images where the loader found them (relative to the scene file), absolutely, so that Blender
    // finds them from wherever it runs.
    const fs::path cwd = fs::current_path();
    fs::current_path(std::string(RAYLAB_SOURCE_DIR) + "/tests");
    const Scene scene = loadScene("../scenes/textured_bricks.json");
    const std::string py = blenderScript(scene);
    fs::current_path(cwd);
    const std::string bricks = (fs::path(RAYLAB_SOURCE_DIR) / "scenes/textures/bricks.ppm").lexically_normal().string();
    const std::string normal =
        (fs::path(RAYLAB_SOURCE_DIR) / "scenes/textures/bricks_normal.ppm").lexically_normal().string();
    EXPECT_EQ(materialLine(py, "brick"),
              "= material(\"brick\", (1, 1, 1, 1.0), (0, 0, 0, 1.0), f0=(0, 0, 0, 1.0), roughness=1, transmission=0, "
              "ior=1.5, metallic=0, albedo_map=(\"" + bricks + "\", \"sRGB\", \"REPEAT\", \"REPEAT\"), normal_map=(\"" +
                  normal + "\", \"Non-Color\", \"REPEAT\", \"REPEAT\"), normal_scale=1)");
    EXPECT_TRUE(fs::is_regular_file(bricks));
    EXPECT_NE(py.find("uvs=[(0, 0), (20, 0), (20, 20), (0, 20)]"), std::string::npos) << "the floor's uvs";
    EXPECT_NE(py.find("node.image.colorspace_settings.name = colour_space"), std::string::npos);
    EXPECT_NE(py.find("nm.space = \"TANGENT\""), std::string::npos);
    // The other slots and the glTF wraps, on a copy of the brick material.
    Scene all = scene;
    Material& m = all.materials[0];
    m.roughnessTextureIndex = m.metallicTextureIndex = m.emissionTextureIndex = m.specularTextureIndex =
        m.albedoTextureIndex;
    all.textures[size_t(m.albedoTextureIndex)].wrapU = TextureWrap::MirroredRepeat;
    all.textures[size_t(m.albedoTextureIndex)].wrapV = TextureWrap::ClampToEdge;
    const std::string line = materialLine(blenderScript(all), "brick");
    for (const char* key : {"albedo_map=", "roughness_map=", "metallic_map=", "normal_map=", "emission_map=", "specular_map="})
        EXPECT_NE(line.find(key), std::string::npos) << key << " in " << line;
    EXPECT_NE(line.find("\"sRGB\", \"MIRROR\", \"EXTEND\")"), std::string::npos) << line;
    EXPECT_NE(py.find("x = smath(tree, \"PINGPONG\", x, 1.0)"), std::string::npos) << "mirrored repeat folds uv";
    EXPECT_NE(py.find("f0 = vmath(tree, \"MULTIPLY\", f0[:3], image(tree, specular_map))"), std::string::npos)
        << "the specular map multiplies f0";
    const fs::path file = scratch() / "textured.py";
    writeBlenderScript(all, file);
    const std::string cmd = "python3 -c \"import ast,sys; ast.parse(open(sys.argv[1]).read())\" '" + file.string() + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << "the exported script is not valid Python";
}

TEST(BenchBlenderExport, GltfMeshesKeepTheirPrimitivesMaterialsAndImages) {
    // Exported by Blender itself (tests/data/blender_suzanne/make_suzanne.py): a gold Suzanne and
    // a checker-textured plane, two primitives of one mesh, the image embedded in the .glb.
    const Scene scene = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/tests/data/blender_suzanne/suzanne.json");
    ASSERT_EQ(scene.meshes.size(), 1u);
    const Mesh& mesh = scene.meshes[0];
    ASSERT_FALSE(mesh.triangleMaterials.empty());
    const fs::path file = scratch() / "suzanne.py";
    writeBlenderScript(scene, file);
    std::ifstream in(file);
    const std::string py((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // Both glTF materials are made, and the mesh takes them as slots with a slot per triangle.
    int gold = -1, checker = -1;
    for (size_t i = 0; i < scene.materials.size(); ++i) {
        if (scene.materials[i].name.find("gold") != std::string::npos) gold = int(i);
        if (scene.materials[i].name.find("checker") != std::string::npos) checker = int(i);
    }
    ASSERT_GE(gold, 0);
    ASSERT_GE(checker, 0);
    const std::string goldLine = materialLine(py, scene.materials[size_t(gold)].name);
    EXPECT_NE(goldLine.find("(0, 0, 0, 1.0), (0, 0, 0, 1.0), f0=(1, 0.71"), std::string::npos)
        << "metallic 1: albedo 0, f0 the base colour: " << goldLine;
    const std::string texture = (fs::absolute(scratch()) / "suzanne_textures" /
                                 ("texture" + std::to_string(scene.materials[size_t(checker)].albedoTextureIndex) + ".exr"))
                                    .lexically_normal()
                                    .string();
    EXPECT_NE(materialLine(py, scene.materials[size_t(checker)].name)
                  .find("albedo_map=(\"" + texture + "\", \"Non-Color\", \"REPEAT\", \"REPEAT\")"),
              std::string::npos)
        << materialLine(py, scene.materials[size_t(checker)].name);
    const std::string slots = ", [mat" + std::to_string(gold) + ", mat" + std::to_string(checker) + "], ";
    const std::string slotsOtherOrder = ", [mat" + std::to_string(checker) + ", mat" + std::to_string(gold) + "], ";
    EXPECT_TRUE(py.find(slots) != std::string::npos || py.find(slotsOtherOrder) != std::string::npos)
        << "the mesh's material slots: the two glTF materials";
    EXPECT_NE(py.find("material_indices=[0, "), std::string::npos);
    EXPECT_NE(py.find(", 1, "), std::string::npos);
    EXPECT_NE(py.find("data.polygons.foreach_set(\"material_index\", material_indices)"), std::string::npos);
    // The embedded image is written where the script looks, top row first, as raylab decoded it.
    const Texture& t = scene.textures[size_t(scene.materials[size_t(checker)].albedoTextureIndex)];
    const Image written = readImage(texture);
    ASSERT_EQ(written.width, t.levels[0].width);
    ASSERT_EQ(written.height, t.levels[0].height);
    const glm::vec4 bottomLeft = t.levels[0].texels[0];   // row 0 = v 0, the image's bottom row
    const size_t lastRow = size_t(written.height - 1) * size_t(written.width) * 4;
    for (int k = 0; k < 4; ++k) EXPECT_FLOAT_EQ(written.rgba[lastRow + size_t(k)], bottomLeft[k]);
    const std::string cmd = "python3 -c \"import ast,sys; ast.parse(open(sys.argv[1]).read())\" '" + file.string() + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << "the exported script is not valid Python";
}

TEST(BenchBlenderExport, OneSidedEmittersMaskTheirBackFaceInCycles) {
    // The Cornell box's light emits downwards alone (emission_sides front); Cycles emits from both
    // faces, so the light's mesh takes a variant of its material whose emission is 1 − Backfacing,
    // and objects that emit from both sides keep the shared material.
    const Scene box = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/cornell_box.json");
    int light = -1;
    for (size_t i = 0; i < box.materials.size(); ++i)
        if (box.materials[i].name == "light") light = int(i);
    ASSERT_GE(light, 0);
    const std::string variant = "mat" + std::to_string(light) + "f";
    const std::string py = blenderScript(box);
    EXPECT_NE(py.find(variant + " = material(\"light (front)\", "), std::string::npos) << py;
    EXPECT_NE(materialLine(py, "light (front)").find(", front_only=True)"), std::string::npos);
    EXPECT_NE(py.find("], " + variant + ", "), std::string::npos) << "the light's mesh takes the variant";
    EXPECT_NE(py.find("smath(tree, \"SUBTRACT\", 1.0, geometry.outputs[\"Backfacing\"])"), std::string::npos);
    const std::string both =
        blenderScript(loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/cornell_box.json", {"objects.5.emission_sides=both"}));
    EXPECT_EQ(both.find(variant + " = "), std::string::npos) << "two-sided: no variant";
    EXPECT_NE(both.find("], mat" + std::to_string(light) + ", "), std::string::npos);
}

TEST(BenchPeerMismatch, MarksAScenePastThreePercentApproximate) {
    const Image raylab = constant(4, 2, 0.5f);
    PeerMismatch near = peerMismatch(raylab, constant(4, 2, 0.51f));   // +2 %
    EXPECT_NEAR(near.meanDifference, 0.02, 1e-6);
    EXPECT_NEAR(near.rmse, 0.01, 1e-6);
    EXPECT_FALSE(near.approximate);
    const PeerMismatch far = peerMismatch(raylab, constant(4, 2, 0.48f));   // −4 %
    EXPECT_NEAR(far.meanDifference, -0.04, 1e-6);
    EXPECT_TRUE(far.approximate);
    EXPECT_FALSE(peerMismatch(raylab, constant(4, 2, 0.514f)).approximate);   // +2.8 %
    EXPECT_TRUE(peerMismatch(raylab, constant(4, 2, 0.516f)).approximate);    // +3.2 %
    const std::string table = peerMismatchTable({{"plain", near}, {"plastics", far}});
    EXPECT_NE(table.find("| plain | 0.5 | 0.51 | +2.00 % | 0.01 | 2.0 % | same image |"), std::string::npos) << table;
    EXPECT_NE(table.find("| plastics | 0.5 | 0.48 | -4.00 % | 0.02 | 4.0 % | approximate: means differ by more than 3 %"),
              std::string::npos)
        << table;
}

TEST(BenchBlenderExport, MeshesTransformsMaterialsThinLensAndSkyMap) {
    Scene scene = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/default.json");
    // 1. A mesh with normals, placed by a transform (kept in y-up terms; placement() converts).
    Mesh mesh;
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
    mesh.triangles = {{0, 1, 2}};
    mesh.material = 1;
    mesh.transform = {{1, 2, 3}, {10, 20, 30}, {2, 2, 2}};
    scene.meshes.push_back(mesh);
    scene.spheres[1].transform = {{0, 1, 0}, {0, 45, 0}, {2, 2, 2}};
    // 2. Glossy plastic, glass.
    scene.materials[1].f0 = glm::vec3(0.04f);
    scene.materials[1].roughness = 0.25f;
    scene.materials[2].transmission = 1.0f;
    scene.materials[2].ior = 1.5f;
    scene.materials[2].roughness = 0.0f;
    // 3. Thin lens.  4. Sky map.
    scene.camera.aperture = 0.1f;
    scene.camera.focusDistance = 0.0f;
    scene.sky.type = Sky::Type::Map;
    scene.sky.map = std::string(RAYLAB_SOURCE_DIR) + "/scenes/sky_procedural.hdr";
    scene.sky.rotation = 30.0f;
    scene.sky.strength = 2.0f;
    const std::string py = blenderScript(scene);
    auto has = [&](const std::string& s) { EXPECT_NE(py.find(s), std::string::npos) << s << "\n" << py; };
    // Vertex (0, 1, 0) y-up is (0, 0, 1) z-up; normal +z is -y.
    has("mesh(\"mesh0\", [(0, -0, 0), (1, -0, 0), (0, -0, 1)], [(0, 1, 2)], [(0, -1, 0), (0, -1, 0), (0, -1, 0)], mat1, "
        "((1, 2, 3), (10, 20, 30), (2, 2, 2)))");
    has("sphere(\"sphere1\", (0, -0, 1), 1, mat");
    has(", ((0, 1, 0), (0, 45, 0), (2, 2, 2)))");
    has("TO_Z_UP @ m @ TO_Z_UP.inverted()");
    has("from_pydata(positions, [], triangles)");
    has("normals_split_custom_set_from_vertices(normals)");
    has("f0=(0.04, 0.04, 0.04, 1.0), roughness=0.25, transmission=0, ior=1.5)");
    has("roughness=0, transmission=1, ior=1.5)");
    has("ShaderNodeBsdfPrincipled");
    has("ShaderNodeBsdfGlass");
    has("glass.distribution = \"SHARP\" if sharp else \"GGX\"");
    has("camera((6, -8, 3.2), (0, -0, 0.8), (0, -0, 1), 32, aperture=0.1, focus_distance=0)");
    has("data.dof.aperture_fstop = data.lens * 1e-3 / (2.0 * aperture)");
    has("scenes/sky_procedural.hdr\", 2, 30)");
    has("ShaderNodeTexEnvironment");
    const fs::path file = scratch() / "scene_full.py";
    writeBlenderScript(scene, file);
    const std::string cmd = "python3 -c \"import ast,sys; ast.parse(open(sys.argv[1]).read())\" '" + file.string() + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << "the exported script is not valid Python";
}

// `raylab-bench [glArgs] convergence` on dir/suite.json, Cycles off, writing into dir: its exit
// status, its log, and the CSV and summary it wrote.
struct SuiteRun {
    int raw = 0;
    std::string log, csv, md;
};
SuiteRun runSuite(const fs::path& dir, const std::string& glArgs = "", const std::string& extraArgs = "") {
    const std::string cmd = std::string("cd '") + RAYLAB_SOURCE_DIR + "' && '" + RAYLAB_BENCH_EXE + "' " + glArgs +
                            "convergence --suite '" + (dir / "suite.json").string() + "' --out '" +
                            (dir / "out").string() + "' --references '" + (dir / "refs").string() +
                            "' --peer off " + extraArgs + " > '" + (dir / "log.txt").string() + "' 2>&1";
    SuiteRun r;
    r.raw = std::system(cmd.c_str());
    const auto read = [](const fs::path& f) {
        std::stringstream text;
        text << std::ifstream(f).rdbuf();
        return text.str();
    };
    r.log = read(dir / "log.txt");
    r.csv = read(dir / "out" / "quick" / "convergence.csv");
    r.md = read(dir / "out" / "quick" / "summary.md");
    return r;
}

// dir/suite.json with one scene, the closed furnace against its analytic value, and one variant
// (rpp 2), at 16×9 with `spp` samples and references and `seeds` seeds.
void writeFurnaceSuite(const fs::path& dir, int spp, int seeds) {
    std::ofstream(dir / "suite.json")
        << R"({"modes": {"quick": {"width": 16, "height": 9, "max_spp": )" << spp << R"(, "seeds": )" << seeds
        << R"(, "reference_spp": )" << spp << R"(, "reference_batches": 2, "peer_max_spp": 2}},
              "scenes": [{"name": "cf", "scene": "scenes/closed_furnace.json", "analytic": 1.0,
                          "variants": [{"name": "rpp2", "set": ["render.rpp=2"]}]}]})";
}

TEST(BenchConvergenceCli, MainCurvesOnlyLeavesTheVariantsOut) {
    // --main-curves-only: each scene's default curve, none of its variants (bench/samplers.md
    // compares shader trees so).
    const fs::path dir = scratch();
    writeFurnaceSuite(dir, 16, 1);
    const SuiteRun run = runSuite(dir, "", "--main-curves-only");
    ASSERT_TRUE(WIFEXITED(run.raw));
    ASSERT_EQ(WEXITSTATUS(run.raw), 0) << run.log;
    EXPECT_NE(run.csv.find("cf,raylab,1,16,"), std::string::npos) << run.csv;
    EXPECT_EQ(run.csv.find("raylab:rpp2"), std::string::npos) << run.csv;
    EXPECT_EQ(run.md.find("raylab:rpp2"), std::string::npos) << run.md;
}

TEST(BenchConvergenceCli, TinySuiteWritesCsvSummaryAndTheCommand) {
    const fs::path dir = scratch();
    writeFurnaceSuite(dir, 64, 2);
    const SuiteRun run = runSuite(dir);
    ASSERT_TRUE(WIFEXITED(run.raw));
    ASSERT_EQ(WEXITSTATUS(run.raw), 0) << run.log;
    const std::string &csv = run.csv, &md = run.md;
    EXPECT_NE(csv.find("scene,renderer,seed,spp,seconds,mse,rmse,relmse"), std::string::npos);
    EXPECT_NE(csv.find("cf,raylab,2,64,"), std::string::npos) << csv;
    EXPECT_NE(md.find("| cf | raylab | analytic [1, 1, 1] | 64 |"), std::string::npos) << md;
    // Two seeds: the CSV adds their mean curve, the row gives the seeds' slope range, the plot draws
    // the mean.
    EXPECT_NE(csv.find("cf,raylab,mean,64,"), std::string::npos) << csv;
    EXPECT_NE(md.find("- seeds: raylab renders each curve with seeds 1 … 2"), std::string::npos) << md;
    EXPECT_NE(md.find(" to -"), std::string::npos) << md;
    // The slope in three decimals, so a slope just short of the goal's −0.6 does not round onto it.
    EXPECT_TRUE(std::regex_search(md, std::regex(R"(\| -[0-9]\.[0-9]{3} \(-)"))) << md;
    // A variant is one more curve of the same scene against the same reference, in the CSV, the
    // table and the plot script.
    EXPECT_NE(csv.find("cf,raylab:rpp2,2,64,"), std::string::npos) << csv;
    EXPECT_NE(md.find("| cf | raylab:rpp2 | analytic [1, 1, 1] | 64 |"), std::string::npos) << md;
    std::stringstream gp;
    gp << std::ifstream(dir / "out" / "quick" / "cf.gp").rdbuf();
    EXPECT_NE(gp.str().find("strcol(2) eq 'raylab:rpp2' && strcol(3) eq 'mean'"), std::string::npos) << gp.str();
    EXPECT_NE(md.find("- command: `"), std::string::npos);
    EXPECT_NE(md.find("--peer off"), std::string::npos);
    // The figures name what made them: the GL renderer and how long the run took.
    EXPECT_NE(md.find("- GL: osmesa | "), std::string::npos) << md;
    EXPECT_NE(md.find("- run time: "), std::string::npos) << md;
    // Each scene starts once untimed (filling Mesa's shader cache) before the timed start-up: both reported.
    EXPECT_TRUE(std::regex_search(run.log, std::regex(R"(raylab start-up: [0-9.]+ s \(the run's first: [0-9.]+ s\))")))
        << run.log;
}

TEST(BenchConvergenceCli, BadSuiteNamesTheFileAndTheKey) {
    const fs::path dir = scratch();
    const std::string cmd = std::string("cd '") + RAYLAB_SOURCE_DIR + "' && '" + RAYLAB_BENCH_EXE +
                            "' convergence --suite '" + (dir / "bad_suite.json").string() + "' --out '" +
                            (dir / "bad_out").string() + "' --peer off > '" + (dir / "bad_log.txt").string() + "' 2>&1";
    // A quick mode with `keys` on a one-scene suite is refused before anything runs: exit 1, the
    // file, the line and column of `at` (the first occurrence of that text in the file), the key
    // path and what is wrong in the message, nothing else (no library's exception text), no summary
    // written.
    const auto refused = [&](const std::string& keys, const std::string& at, const std::string& message,
                             const std::string& sceneEntry = R"({"name": "f", "scene": "scenes/furnace.json", "analytic": 0.5})") {
        SCOPED_TRACE(keys + " " + sceneEntry);
        const std::string text = R"({"modes": {"quick": {"width": 8, "height": 8, "max_spp": 4, )" + keys +
                                 R"(, "reference_spp": 4, "reference_batches": 2}},
            "scenes": [)" + sceneEntry + "]}";
        std::ofstream(dir / "bad_suite.json") << text;
        const std::size_t offset = text.find(at);
        ASSERT_NE(offset, std::string::npos);
        const std::size_t lineStart = text.rfind('\n', offset);
        const int line = 1 + int(std::count(text.begin(), text.begin() + long(offset), '\n'));
        const int column = int(offset - (lineStart == std::string::npos ? 0 : lineStart + 1)) + 1;
        const int raw = std::system(cmd.c_str());
        std::stringstream whole;
        whole << std::ifstream(dir / "bad_log.txt").rdbuf();
        // The first line names the GL renderer; the error is the rest.
        std::stringstream log;
        for (std::string text_line; std::getline(whole, text_line);)
            if (text_line.rfind("GL: ", 0) != 0) log << text_line << "\n";
        ASSERT_TRUE(WIFEXITED(raw));
        EXPECT_EQ(WEXITSTATUS(raw), 1) << whole.str();
        const std::string where = (dir / "bad_suite.json").string() + ":" + std::to_string(line) + ":" +
                                  std::to_string(column) + ": error: ";
        if (message.empty())   // the parser's own wording: only where it is and that it is ours
            EXPECT_EQ(log.str().rfind(where, 0), 0u) << log.str();
        else
            EXPECT_EQ(log.str(), where + message + "\n");
        EXPECT_EQ(log.str().find("json.exception"), std::string::npos) << log.str();
        EXPECT_FALSE(fs::exists(dir / "bad_out" / "quick" / "summary.md"));
    };
    // peer_timing_runs is how many Blender runs give each Cycles point its median time: zero
    // would leave a point with no time.
    refused(R"("seeds": 1, "peer_max_spp": 1, "peer_timing_runs": 0)", "0, \"reference_spp\"",
            "modes.quick.peer_timing_runs: must be at least 1, got 0");
    // peer_extend_spp is where Cycles' curve may go on to: below peer_max_spp it is refused too.
    refused(R"("seeds": 1, "peer_max_spp": 8, "peer_extend_spp": 4)", "4, \"reference_spp\"",
            "modes.quick.peer_extend_spp: must be at least peer_max_spp (8), got 4");
    // peer_decide_spp is where it may go on to while its bound does not decide the goal: below
    // peer_extend_spp it is refused.
    refused(R"("seeds": 1, "peer_max_spp": 8, "peer_extend_spp": 16, "peer_decide_spp": 8)", "8, \"reference_spp\"",
            "modes.quick.peer_decide_spp: must be at least peer_extend_spp (16), got 8");
    // extend_spp is where raylab's curves may go on to: below max_spp it is refused.
    refused(R"("seeds": 1, "peer_max_spp": 1, "extend_spp": 2)", "2, \"reference_spp\"",
            "modes.quick.extend_spp: must be at least max_spp (4), got 2");
    // seeds is how many raylab curves each row averages: zero would leave a row with no curve.
    refused(R"("seeds": 0, "peer_max_spp": 1)", "0,", "modes.quick.seeds: must be at least 1, got 0");
    // A value of the wrong type is named by its key path, not by the JSON library's exception.
    refused(R"("seeds": 1, "peer_max_spp": 1, "peer_thresholds": "yes")", "\"yes\"",
            "modes.quick.peer_thresholds: expected an array of noise thresholds, got string");
    refused(R"("seeds": 1, "peer_max_spp": 1, "peer_thresholds": [0.1, 1.5])", "1.5",
            "modes.quick.peer_thresholds[1]: expected a noise threshold in (0, 1), got 1.5");
    // Decreasing, so that the runs stop at the first that reaches every level.
    refused(R"("seeds": 1, "peer_max_spp": 1, "peer_thresholds": [0.01, 0.02])", "0.02",
            "modes.quick.peer_thresholds[1]: the thresholds must decrease, and 0.02 follows 0.01");
    refused(R"("seeds": 1.5, "peer_max_spp": 1)", "1.5", "modes.quick.seeds: expected an integer, got 1.5");
    refused(R"("seeds": 1, "peer_max_spp": "8")", "\"8\"", "modes.quick.peer_max_spp: expected an integer, got string");
    // A misspelt key is refused at the key, with the closest known one, as in a scene file.
    refused(R"("seeds": 1, "peer_max_spp": 1, "peer_timing_run": 3)", "\"peer_timing_run\"",
            "modes.quick.peer_timing_run: unknown key 'peer_timing_run' in modes.quick; did you mean 'peer_timing_runs'?");
    // A missing key is reported at the object that lacks it.
    refused(R"("seeds": 1)", "{\"width\"", "modes.quick: missing key 'peer_max_spp'");
    // The scenes are checked the same way.
    refused(R"("seeds": 1, "peer_max_spp": 1)", "true", "scenes[0].analytic: expected a number >= 0 (the image's exact value), got boolean",
            R"({"name": "f", "scene": "scenes/furnace.json", "analytic": true})");
    refused(R"("seeds": 1, "peer_max_spp": 1)", "\"render.nee\"", "scenes[0].variants[0].set[0]: expected a KEY=VALUE string, got \"render.nee\"",
            R"({"name": "f", "scene": "scenes/furnace.json", "variants": [{"name": "v", "set": ["render.nee"]}]})");
    // A syntax error is located too (here the missing value after "seeds":).
    refused(R"("seeds": , "peer_max_spp": 1)", ", \"peer_max_spp\"", "");
    // --only with a name the suite lacks lists the names it has.
    std::ofstream(dir / "bad_suite.json") << R"({"modes": {"quick": {"width": 8, "height": 8, "max_spp": 4, "seeds": 1,
        "peer_max_spp": 1, "reference_spp": 4, "reference_batches": 2}},
        "scenes": [{"name": "f", "scene": "scenes/furnace.json", "analytic": 0.5}]})";
    const std::string onlyCmd = std::string("cd '") + RAYLAB_SOURCE_DIR + "' && '" + RAYLAB_BENCH_EXE +
                                "' convergence --suite '" + (dir / "bad_suite.json").string() + "' --out '" +
                                (dir / "bad_out").string() + "' --peer off --only g 2>&1";
    std::string out;
    {
        std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(onlyCmd.c_str(), "r"), pclose);
        ASSERT_TRUE(pipe);
        char buf[512];
        while (fgets(buf, sizeof buf, pipe.get())) out += buf;
        const int raw = pclose(pipe.release());
        ASSERT_TRUE(WIFEXITED(raw));
        EXPECT_EQ(WEXITSTATUS(raw), 1) << out;
    }
    EXPECT_NE(out.find("--only: error: no scene named 'g' in " + (dir / "bad_suite.json").string() + " (scenes: f)"),
              std::string::npos)
        << out;
}

TEST(BenchConvergenceCli, APeerSceneThatMissesAGoalLevelGoesOnToExtendSpp) {
    // At 8×8 and 4 spp the default scene is far from 2 % of its mean, so with extend_spp 16 its
    // two seeds are rendered again up to 16 spp; its variant and the analytic furnace, which the
    // goal does not judge, stop at max_spp.
    const fs::path dir = scratch() / "extend";
    fs::create_directories(dir);
    std::ofstream(dir / "suite.json") << R"({"modes": {"quick": {"width": 8, "height": 8, "max_spp": 4, "seeds": 2,
        "extend_spp": 16, "reference_spp": 4, "reference_batches": 2, "peer_max_spp": 1}},
        "scenes": [{"name": "f", "scene": "scenes/furnace.json", "analytic": 0.5},
                   {"name": "d", "scene": "scenes/default.json", "peer": true,
                    "variants": [{"name": "bsdf", "set": ["render.nee=false"]}]}]})";
    const SuiteRun run = runSuite(dir);
    ASSERT_TRUE(WIFEXITED(run.raw));
    ASSERT_EQ(WEXITSTATUS(run.raw), 0) << run.log;
    const std::string &csv = run.csv, &md = run.md;
    for (const char* row : {"d,raylab,1,16,", "d,raylab,2,16,", "d,raylab,mean,16,", "d,raylab:bsdf,2,4,", "f,raylab,1,4,"})
        EXPECT_NE(csv.find(row), std::string::npos) << row << "\n" << csv;
    for (const char* row : {"d,raylab:bsdf,1,8,", "f,raylab,1,8,"})
        EXPECT_EQ(csv.find(row), std::string::npos) << row << "\n" << csv;
    EXPECT_NE(md.find("| d | raylab | mean of 2 raylab renders × 4 spp | 16 |"), std::string::npos) << md;
    EXPECT_NE(md.find("and on up to 16 where its seeds' mean has not reached a goal level"), std::string::npos)
        << md;
}

TEST(BenchConvergenceCli, RunsThroughEglAndSaysSo) {
    // The benchmark a GPU machine runs: `--gl egl` (a GPU device when present, else Mesa's
    // surfaceless llvmpipe), and the summary names the context so figures carry their hardware.
    try {
        createEglContext();
    } catch (const std::exception& e) {
        GTEST_SKIP() << "no EGL here: " << e.what();
    }
    const fs::path dir = scratch();
    std::ofstream(dir / "suite.json") << R"({"modes": {"quick": {"width": 8, "height": 8, "max_spp": 4, "seeds": 1,
        "reference_spp": 4, "reference_batches": 2, "peer_max_spp": 1}},
        "scenes": [{"name": "f", "scene": "scenes/furnace.json", "analytic": 0.5}]})";
    const SuiteRun run = runSuite(dir, "--gl egl ");
    ASSERT_TRUE(WIFEXITED(run.raw) && WEXITSTATUS(run.raw) == 0) << run.log;
    EXPECT_NE(run.md.find("- GL: egl-"), std::string::npos) << run.md;
    EXPECT_NE(run.md.find("| f | raylab | analytic [0.5, 0.5, 0.5] | 4 |"), std::string::npos) << run.md;
}

TEST(BenchScalingCli, WritesBothSeriesWithTheCommand) {
    const fs::path dir = scratch() / "scaling";
    const std::string cmd = std::string("cd '") + RAYLAB_SOURCE_DIR + "' && '" + RAYLAB_BENCH_EXE +
                            "' scaling --spp 1 --repeat 1 --out '" + dir.string() + "' > /dev/null 2>&1";
    const int raw = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(raw));
    ASSERT_EQ(WEXITSTATUS(raw), 0);
    std::stringstream md, csv;
    md << std::ifstream(dir / "scaling.md").rdbuf();
    csv << std::ifstream(dir / "scaling.csv").rdbuf();
    for (const char* s : {"## Against sphere count", "## Against resolution", "| 512 |", "| 1280×720 |", "scaling --spp 1"})
        EXPECT_NE(md.str().find(s), std::string::npos) << s;
    EXPECT_NE(csv.str().find("resolution,32,1280,720,"), std::string::npos);
}
