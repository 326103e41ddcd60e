// raylab-render --resume: a render continued from its EXR equals one uninterrupted run bit for bit,
// and an EXR that does not belong to the scene and settings given is refused, left as it was.
#include "io/image_io.h"

#include "support/render_cli.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <fstream>

namespace fs = std::filesystem;

namespace {

using raylab::test::CliRun;
using raylab::test::slurp;

fs::path scratchDir() { return raylab::test::scratchDir("raylab_resume_test"); }

CliRun render(const std::string& args) { return raylab::test::runRender(args + " -q", scratchDir()); }

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

// Bit for bit: the float32 pixels compared as bytes, and their count.
::testing::AssertionResult samePixels(const fs::path& a, const fs::path& b) {
    const raylab::Image x = raylab::readImage(a), y = raylab::readImage(b);
    if (x.width != y.width || x.height != y.height) return ::testing::AssertionFailure() << "sizes differ";
    std::size_t differ = 0;
    for (std::size_t i = 0; i < x.rgba.size(); ++i)
        differ += std::memcmp(&x.rgba[i], &y.rgba[i], sizeof(float)) != 0;
    if (differ) return ::testing::AssertionFailure() << differ << " of " << x.rgba.size() << " channels differ";
    return ::testing::AssertionSuccess();
}

// Even sampling; adaptive renders (the default) have their own case below.
const std::string kScene = "scenes/default.json --width 12 --height 8 --set render.max_bounces=3 --set render.adaptive=false";

} // namespace

// Splits at pass boundaries (multiples of rpp), once and twice, for the independent and the Sobol
// sampler. The test can fail: a resumed run that restarted the mean, skipped or repeated samples,
// or restored the image flipped would differ in almost every channel.
TEST(RenderResume, ResumedRendersEqualUninterruptedOnesBitForBit) {
    struct Split {
        int rpp;
        std::vector<int> stops;   // spp of each run, the last the target
    };
    const std::vector<Split> splits = {{1, {3, 8}}, {2, {4, 10}}, {2, {2, 6, 10}}, {3, {3, 9}}};
    const fs::path dir = scratchDir();
    for (const char* sampler : {"independent", "sobol"}) {
        for (const Split& s : splits) {
            const std::string common = kScene + " --set render.sampler=" + sampler + " --rpp " + std::to_string(s.rpp);
            const std::string label = std::string(sampler) + " rpp " + std::to_string(s.rpp) + " to " +
                                      std::to_string(s.stops.back());
            const fs::path whole = dir / "whole.exr", parts = dir / "parts.exr";
            ASSERT_EQ(render(common + " --spp " + std::to_string(s.stops.back()) + " -o " + quoted(whole)).status, 0);
            CliRun r = render(common + " --spp " + std::to_string(s.stops[0]) + " -o " + quoted(parts));
            ASSERT_EQ(r.status, 0) << r.err;
            EXPECT_FALSE(samePixels(whole, parts)) << label << ": the first part alone must differ";
            for (std::size_t k = 1; k < s.stops.size(); ++k) {
                r = render(common + " --spp " + std::to_string(s.stops[k]) + " --resume " + quoted(parts));
                ASSERT_EQ(r.status, 0) << label << ": " << r.err;
            }
            EXPECT_TRUE(samePixels(whole, parts)) << label;
            const raylab::RenderMetadata m = raylab::readRenderMetadata(parts);
            EXPECT_EQ(m.spp, std::uint64_t(s.stops.back())) << label;
            EXPECT_EQ(m.passes, raylab::readRenderMetadata(whole).passes) << label;
        }
    }
}

TEST(RenderResume, RefusesAnotherSceneOrSettingsAndLeavesTheFileAlone) {
    const fs::path dir = scratchDir();
    const fs::path exr = dir / "r.exr";
    ASSERT_EQ(render(kScene + " --spp 2 -o " + quoted(exr)).status, 0);
    const std::string bytes = slurp(exr);
    struct Case {
        std::string args;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {kScene + " --spp 4 --seed 9", "raylab:seed is 1 in the EXR but render.seed 9"},
        {kScene + " --spp 4 --rpp 2", "raylab:rpp"},
        {kScene + " --spp 4 --set render.sampler=independent", "raylab:sampler"},
        {kScene + " --spp 4 --set camera.fov=20", "raylab:settings_hash differs"},
        {"scenes/furnace.json --width 12 --height 8 --set render.max_bounces=3 --set render.adaptive=false --spp 4",
         "raylab:settings_hash differs"},
        {kScene + " --spp 1", "holds 2 spp already"},
        {kScene + " --spp 4 --tracer compute", "raylab:tracer"},
        {kScene + " --spp 4 --set render.adaptive=true", "render.adaptive is in effect"},
        {"scenes/default.json --width 12 --height 8 --set render.max_bounces=3 --spp 4",
         "the EXR has no adaptive.samples channel: it was rendered with even sampling (resume it with --set "
         "render.adaptive=false)"},
    };
    for (const Case& c : cases) {
        const CliRun r = render(c.args + " --resume " + quoted(exr));
        EXPECT_EQ(r.status, 1) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(exr.string() + ": error: cannot resume"), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_EQ(slurp(exr), bytes) << c.args << ": the EXR must be left as it was";
    }
    const CliRun v = render(kScene + " --spp 4 --resume " + quoted(exr) + " --debug-view normals");
    EXPECT_EQ(v.status, 2) << v.err;
    EXPECT_EQ(slurp(exr), bytes);
}

TEST(RenderResume, RefusesFilesRaylabDidNotWrite) {
    const fs::path dir = scratchDir();
    const fs::path png = dir / "p.png";
    ASSERT_EQ(render(kScene + " --spp 1 -o " + quoted(png)).status, 0);
    CliRun r = render(kScene + " --spp 2 --resume " + quoted(png) + " -o " + quoted(dir / "x.exr"));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find(png.string() + ": error: not an EXR that raylab-render wrote"), std::string::npos) << r.err;

    // An EXR from elsewhere: the pixels but no raylab attributes.
    const fs::path plain = dir / "plain.exr";
    {
        auto out = OIIO::ImageOutput::create(plain.string());
        ASSERT_TRUE(out);
        const OIIO::ImageSpec spec(12, 8, 4, OIIO::TypeDesc::FLOAT);
        std::vector<float> pixels(12 * 8 * 4, 0.5f);
        ASSERT_TRUE(out->open(plain.string(), spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
        ASSERT_TRUE(out->close());
    }
    const std::string bytes = slurp(plain);
    r = render(kScene + " --spp 2 --resume " + quoted(plain));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find(plain.string() + ": error: not an EXR that raylab-render wrote: no string attribute raylab:version"),
              std::string::npos) << r.err;
    EXPECT_EQ(slurp(plain), bytes);

    const fs::path garbage = dir / "garbage.exr";
    std::ofstream(garbage) << "not an image";
    r = render(kScene + " --spp 2 --resume " + quoted(garbage));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find(garbage.string() + ": error: cannot read"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("terminate"), std::string::npos) << r.err;
}

// The stratified sampler's strata depend on the run's target: a resume to another target would not
// be the run it claims to be, so it is refused with the target it can take.
TEST(RenderResume, StratifiedResumesOnlyToItsRecordedTarget) {
    const fs::path exr = scratchDir() / "s.exr";
    const std::string common = kScene + " --set render.sampler=stratified";
    ASSERT_EQ(render(common + " --spp 4 -o " + quoted(exr)).status, 0);
    const CliRun r = render(common + " --spp 8 --resume " + quoted(exr));
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("resume it to --spp 4"), std::string::npos) << r.err;
    EXPECT_EQ(render(common + " --spp 4 --resume " + quoted(exr)).status, 0) << "already at its target: nothing to add";
}

// The resume continues the mean in the file: adding 1 to every pixel of a 3 spp EXR before
// resuming it to 8 spp raises the result by 3/8 against the uninterrupted run (a resume that
// rendered from 0 again would equal that run).
TEST(RenderResume, TheResumedMeanStartsFromThePixelsInTheExr) {
    const fs::path dir = scratchDir();
    const fs::path whole = dir / "w.exr", part = dir / "p.exr";
    ASSERT_EQ(render(kScene + " --spp 8 -o " + quoted(whole)).status, 0);
    ASSERT_EQ(render(kScene + " --spp 3 -o " + quoted(part)).status, 0);
    {
        auto in = OIIO::ImageInput::open(part.string());
        ASSERT_TRUE(in);
        const OIIO::ImageSpec spec = in->spec();
        std::vector<float> pixels(std::size_t(spec.width) * std::size_t(spec.height) * std::size_t(spec.nchannels));
        ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
        in->close();
        for (std::size_t i = 0; i < pixels.size(); ++i)
            if (i % 4 != 3) pixels[i] += 1.0f;
        auto out = OIIO::ImageOutput::create(part.string());
        ASSERT_TRUE(out && out->open(part.string(), spec));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
        ASSERT_TRUE(out->close());
    }
    const CliRun r = render(kScene + " --spp 8 --resume " + quoted(part));
    ASSERT_EQ(r.status, 0) << r.err;
    const raylab::Image a = raylab::readImage(whole), b = raylab::readImage(part);
    for (std::size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 != 3) {
            ASSERT_NEAR(b.rgba[i] - a.rgba[i], 3.0f / 8.0f, 1e-4f) << "channel " << i;
        }
    }
}

// An adaptive render (the default) keeps its per-pixel samples, half image and gain gate in its EXR:
// stopped where the warm-up ends (16 spp, two whole passes) and resumed, it is the uninterrupted
// render bit for bit, blocks of different counts and all. An EXR whose counts are not a render's
// own (a block's pixels apart, or a mean that is not raylab:spp) is refused.
TEST(RenderResume, AdaptiveRendersGoOnFromTheirExr) {
    const std::string scene = "scenes/cornell_box.json --width 32 --height 18 --rpp 8";
    const fs::path dir = scratchDir();
    const fs::path whole = dir / "aw.exr", parts = dir / "ap.exr";
    ASSERT_EQ(render(scene + " --spp 48 -o " + quoted(whole)).status, 0);
    ASSERT_EQ(render(scene + " --spp 16 -o " + quoted(parts)).status, 0);
    EXPECT_FALSE(samePixels(whole, parts));
    const CliRun r = render(scene + " --spp 48 --resume " + quoted(parts));
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_TRUE(samePixels(whole, parts));
    const auto wholeState = raylab::readAdaptiveState(whole), partsState = raylab::readAdaptiveState(parts);
    ASSERT_TRUE(wholeState && partsState);
    EXPECT_EQ(partsState->samples, wholeState->samples);
    EXPECT_NE(std::adjacent_find(wholeState->samples.begin(), wholeState->samples.end(), std::not_equal_to<>()),
              wholeState->samples.end()) << "the blocks should hold different counts";
    EXPECT_EQ(raylab::readRenderMetadata(parts).spp, raylab::readRenderMetadata(whole).spp);

    // Counts that are not the render's.
    const fs::path forged = dir / "af.exr";
    const raylab::RenderMetadata meta = raylab::readRenderMetadata(whole);
    struct Forgery {
        std::function<void(raylab::AdaptiveState&)> change;
        std::string expected;
    };
    const std::vector<Forgery> forgeries = {
        {[](raylab::AdaptiveState& a) { a.samples[1] += 1; }, "adaptive.samples: pixel (1, 0) holds"},
        {[](raylab::AdaptiveState& a) {
             for (int y = 14; y < 18; ++y)   // the bottom-left block: blocks count from GL's bottom row
                 for (int x = 0; x < 4; ++x) a.samples[std::size_t(y * 32 + x)] += 64;
         },
         "adaptive.samples averages"},
    };
    for (const Forgery& f : forgeries) {
        raylab::AdaptiveState state = *wholeState;
        f.change(state);
        raylab::writeImage(forged, raylab::readImage(whole), meta, {}, &state);
        const std::string bytes = slurp(forged);
        const CliRun bad = render(scene + " --spp 64 --resume " + quoted(forged));
        EXPECT_EQ(bad.status, 1) << bad.err;
        EXPECT_NE(bad.err.find(forged.string() + ": error: cannot resume: " + f.expected), std::string::npos) << bad.err;
        EXPECT_EQ(slurp(forged), bytes);
    }
}
