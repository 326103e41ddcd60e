// The strip the fragment entry draws small images in (shaders/include/fragment_layout.glsl): every
// pixel once, equal shares per rasteriser tile, and the very same image as without it.
#include "render_helpers.h"
#include "support/gl_test.h"
#include "support/statistics.h"

#include "render/adaptive_sampling.h"
#include "render/path_tracer.h"
#include "shaders/include/fragment_layout.glsl"

#include <algorithm>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

using namespace raylab;

namespace {

// Pixels traced per 64×64 tile of the drawn area (strip or image), tiles row by row.
std::vector<int> tileLoads(int width, int height, int tiles) {
    const glm::ivec2 drawn = fragmentStripSize(width, height, tiles);
    const int tilesX = (drawn.x + glsl::RASTER_TILE - 1) / glsl::RASTER_TILE;
    const int tilesY = (drawn.y + glsl::RASTER_TILE - 1) / glsl::RASTER_TILE;
    std::vector<int> loads(size_t(tilesX * tilesY), 0);
    for (int y = 0; y < drawn.y; ++y)
        for (int x = 0; x < drawn.x; ++x) {
            const glm::ivec2 p = glsl::fragmentPixel({x, y}, {width, height}, tiles);
            if (p.x < width && p.y < height) ++loads[size_t(y / glsl::RASTER_TILE * tilesX + x / glsl::RASTER_TILE)];
        }
    return loads;
}

// The pass's length in pixels when `threads` threads take tiles from one queue in order (as
// llvmpipe's do), over the ideal: pixels / threads.
double queueSlowdown(const std::vector<int>& loads, int threads) {
    std::vector<long> busy(size_t(threads), 0);
    long total = 0;
    for (int load : loads) {
        *std::min_element(busy.begin(), busy.end()) += load;
        total += load;
    }
    return double(*std::max_element(busy.begin(), busy.end())) / (double(total) / threads);
}

} // namespace

TEST(FragmentLayout, TheStripTracesEveryPixelOnce) {
    for (const auto& [w, h] : {std::pair{96, 54}, {160, 90}, {1, 1}, {7, 3}, {33, 65}, {255, 17}, {5, 200}})
        for (int threads : {2, 3, 4, 16}) {
            SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + ", " + std::to_string(threads) + " threads");
            const int tiles = fragmentStripTiles(w, h, threads);
            const glm::ivec2 drawn = fragmentStripSize(w, h, tiles);
            std::vector<int> seen(size_t(w * h), 0);
            for (int y = 0; y < drawn.y; ++y)
                for (int x = 0; x < drawn.x; ++x) {
                    const glm::ivec2 p = glsl::fragmentPixel({x, y}, {w, h}, tiles);
                    ASSERT_GE(p.x, 0);
                    ASSERT_GE(p.y, 0);
                    if (p.x < w && p.y < h) ++seen[size_t(p.y * w + p.x)];
                }
            EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), w * h) << "strip tiles " << tiles;
        }
}

TEST(FragmentLayout, AListedStripTracesItsBlocksOnceAndNoOtherPixel) {
    // An adaptive round's strip lists the blocks that take it (adaptiveBlocks[]): its fragments
    // cover exactly their pixels, each once, whatever the blocks and the tiles.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    for (const glm::ivec2 image : {glm::ivec2{96, 54}, glm::ivec2{37, 21}, glm::ivec2{640, 360}})
        for (int tiles : {1, 2, 8}) {
            const AdaptiveBlocks blocks{image.x, image.y};
            std::vector<int> listed;
            for (int b = 0; b < blocks.count(); ++b)
                if (uniform(rng) < 0.3) listed.push_back(b);
            const glm::ivec2 drawn = glsl::fragmentStripExtent(int(listed.size()), tiles);
            std::vector<int> traced(size_t(image.x * image.y), 0);
            for (int y = 0; y < drawn.y; ++y)
                for (int x = 0; x < drawn.x; ++x) {
                    const int slot = glsl::fragmentSlot({x, y}, tiles);
                    if (slot >= int(listed.size())) continue;
                    const glm::ivec2 p = glsl::blockPixel(listed[size_t(slot)], {x, y}, image);
                    if (p.x < image.x && p.y < image.y) ++traced[size_t(p.y * image.x + p.x)];
                }
            for (int y = 0; y < image.y; ++y)
                for (int x = 0; x < image.x; ++x) {
                    const bool isListed = std::binary_search(listed.begin(), listed.end(), blocks.blockOf(x, y));
                    ASSERT_EQ(traced[size_t(y * image.x + x)], isListed ? 1 : 0)
                        << image.x << "x" << image.y << ", " << tiles << " tiles, pixel " << x << "," << y;
                }
        }
}

TEST(FragmentLayout, AnAdaptiveRoundsStripFitsTheFramebufferForEveryImageSize) {
    // The strip of every block of an image up to the largest render.width × height allowed.
    const auto blocks = [](int w, int h) { return AdaptiveBlocks{w, h}.count(); };
    EXPECT_EQ(adaptiveStripTiles(blocks(96, 54), 2, 2), 2) << "a small image keeps its strip";
    EXPECT_EQ(adaptiveStripTiles(blocks(640, 360), 0, 2), 2);
    for (const glm::ivec2 size : {glm::ivec2{640, 360}, glm::ivec2{1920, 1080}, glm::ivec2{3840, 2160},
                                  glm::ivec2{16384, 16384}, glm::ivec2{16384, 1}, glm::ivec2{1, 16384}})
        for (int threads : {1, 2, 16}) {
            const int tiles = adaptiveStripTiles(blocks(size.x, size.y), 0, threads);
            const glm::ivec2 strip = glsl::fragmentStripExtent(blocks(size.x, size.y), tiles);
            EXPECT_LE(strip.x, kMaxStripWidth) << size.x << "x" << size.y << ", " << threads << " threads";
            EXPECT_LE(strip.y, 16384) << size.x << "x" << size.y << ", " << threads << " threads";
            EXPECT_TRUE(strip.y <= kMaxAdaptiveStripHeight || strip.x == kMaxStripWidth)
                << size.x << "x" << size.y << ": taller than needed";
        }
}

TEST(FragmentLayout, SmallImagesShareTilesEquallyAndLargeOnesKeepTheirPixels) {
    // 96×54 (the quick benchmark's size) as itself: a 64-wide tile and a 32-wide one, so two
    // threads take 4/3 of the ideal time; its strip brings that under 10 %.
    EXPECT_NEAR(queueSlowdown(tileLoads(96, 54, 0), 2), 4.0 / 3.0, 1e-9);
    for (const auto& [w, h] : {std::pair{96, 54}, {160, 90}, {130, 70}, {200, 120}})   // ≥ 60 blocks a thread
        for (int threads : {2, 4, 8}) {
            SCOPED_TRACE(std::to_string(w) + "x" + std::to_string(h) + ", " + std::to_string(threads) + " threads");
            const int tiles = fragmentStripTiles(w, h, threads);
            if (tiles == 0) continue;
            EXPECT_LT(queueSlowdown(tileLoads(w, h, tiles), threads), 1.1);
        }
    EXPECT_GT(fragmentStripTiles(96, 54, 2), 0);
    EXPECT_EQ(fragmentStripTiles(640, 360, 2), 0) << "60 tiles: the queue balances itself";
    EXPECT_EQ(fragmentStripTiles(96, 54, 1), 0) << "one thread: nothing to balance";
}

class FragmentLayoutRenderTest : public test::GlTest {};

TEST_F(FragmentLayoutRenderTest, TheStripRendersTheSameImageBitForBit) {
    // Each pixel takes the same samples wherever its fragment lies; only the order of the
    // fragments changes.
    const Scene scene = loadScene(test::scenePath("cornell_box.json"),
                                  {"render.width=96", "render.height=54", "render.spp=4", "render.rpp=2"});
    // Four rasteriser threads as the tracer counts them (llvmpipe read its own count already),
    // so the strip is drawn on any machine.
    const char* before = std::getenv("LP_NUM_THREADS");
    const std::string saved = before ? before : "";
    ::setenv("LP_NUM_THREADS", "4", 1);
    ASSERT_GT(fragmentStripTiles(96, 54, rasterThreads()), 0);
    TracerOptions strip;
    TracerOptions plain;
    plain.balanceTiles = false;
    const Image a = test::render(scene, strip);
    const Image b = test::render(scene, plain);
    if (before) ::setenv("LP_NUM_THREADS", saved.c_str(), 1);
    else ::unsetenv("LP_NUM_THREADS");
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    for (size_t i = 0; i < a.rgba.size(); ++i) ASSERT_EQ(a.rgba[i], b.rgba[i]) << i;
    EXPECT_GT(test::mean(test::channel(a, 0)), 0.01) << "the box is lit";
}

TEST_F(FragmentLayoutRenderTest, AnAdaptiveRoundsListedStripRendersTheSameImageBitForBit) {
    // An adaptive pass's rounds draw only the blocks that take them (uploadPlan's list); drawn
    // without the list, every fragment runs and the others skip by the plan. The same samples
    // either way, so the same image, with blocks that sat passes out and blocks of several rounds.
    const Scene scene = loadScene(test::scenePath("cornell_box.json"), {"render.width=48", "render.height=27",
                                                                        "render.spp=96", "render.rpp=8",
                                                                        "render.adaptive=true"});
    TracerOptions plain;
    plain.balanceTiles = false;
    PathTracer listed, unlisted(plain);
    listed.setScene(scene);
    unlisted.setScene(scene);
    for (int pass = 0; pass < 8; ++pass) {
        listed.renderPass(8);
        unlisted.renderPass(8);
    }
    ASSERT_TRUE(listed.adaptive());
    const std::vector<std::uint64_t>& samples = listed.blockSamples();
    ASSERT_EQ(samples, unlisted.blockSamples());
    EXPECT_NE(*std::min_element(samples.begin(), samples.end()), *std::max_element(samples.begin(), samples.end()))
        << "some blocks should have sat passes out";
    const Image a = listed.readImage(), b = unlisted.readImage();
    ASSERT_EQ(a.rgba.size(), b.rgba.size());
    for (size_t i = 0; i < a.rgba.size(); ++i) ASSERT_EQ(a.rgba[i], b.rgba[i]) << i;
}
