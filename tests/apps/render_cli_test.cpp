// raylab-render as a user runs it: exit codes, messages, outputs, Ctrl-C.
#include "io/image_io.h"
#include "render/debug_views.h"
#include "support/render_cli.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <fstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

using raylab::test::CliRun;
using raylab::test::slurp;

fs::path scratchDir() { return raylab::test::scratchDir("raylab_cli_test"); }

// Runs raylab-render with the arguments (shell-quoted by the caller) from the repository root.
CliRun render(const std::string& args) { return raylab::test::runRender(args, scratchDir()); }

fs::path writeScene(const std::string& name, const std::string& text) {
    const fs::path p = scratchDir() / name;
    std::ofstream(p) << text;
    return p;
}

const char* kSmall = " --width 16 --height 9 --spp 2 -q";

} // namespace

TEST(RenderCli, HelpDocumentsEveryOption) {
    const CliRun r = render("--help");
    EXPECT_EQ(r.status, 0);
    for (const char* opt : {"--output", "--spp", "--time", "--width", "--height", "--seed", "--set", "--rpp",
                            "--gl", "--quiet", "--debug-view", "Exit status"})
        EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
}

TEST(RenderCli, RendersPngAndExrAndPrintsThePath) {
    const fs::path png = scratchDir() / "d.png";
    CliRun r = render("scenes/default.json" + std::string(kSmall) + " -o '" + png.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find(png.string()), std::string::npos) << r.out;
    EXPECT_TRUE(fs::exists(png));

    const fs::path exr = scratchDir() / "d.exr";
    r = render("scenes/default.json --width 16 --height 9 --spp 3 --seed 77 -o '" + exr.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("3/3 spp"), std::string::npos) << "progress line: " << r.err;
    EXPECT_NE(r.err.find("Mpaths/s"), std::string::npos) << r.err;
    auto in = OIIO::ImageInput::open(exr.string());
    ASSERT_TRUE(in);
    EXPECT_EQ(in->spec().width, 16);
    EXPECT_EQ(in->spec().get_int_attribute("raylab:spp"), 3);
    EXPECT_EQ(in->spec().get_int_attribute("raylab:seed"), 77);
    EXPECT_EQ(in->spec().get_string_attribute("raylab:sampler"), "sobol");   // the default
    EXPECT_NE(in->spec().get_string_attribute("raylab:scene").find("default.json"), std::string::npos);
}

TEST(RenderCli, SetOverridesAnyKey) {
    const fs::path exr = scratchDir() / "s.exr";
    const CliRun r = render("scenes/furnace.json --set sky.strength=2 --set render.spp=1 -q --width 4 --height 4 -o '" +
                         exr.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    const raylab::Image im = raylab::readImage(exr);
    EXPECT_NEAR(im.rgba[0], 1.0f, 1e-6f);   // albedo 0.5 × sky 1 × strength 2
}

TEST(RenderCli, BadScenesFailWithLocatedMessages) {
    struct Case {
        std::string text;
        std::string expected;
    };
    const std::vector<Case> cases = {
        {"{\n  \"objects\": [\n    {\"type\": \"sphere\",, }\n  ]\n}\n", "bad.json:3:"},
        {R"({"objects": [{"type": "sphere", "radus": 1}]})", "did you mean 'radius'"},
        {R"({"objects": [{"type": "sphere", "radius": -1}]})", "objects[0].radius"},
        {R"({"objects": [{"type": "sphere", "radius": 1e999}]})", "objects[0].radius"},
        {R"({"objects": [{"type": "sphere", "radius": "big"}]})", "objects[0].radius"},
        {R"({"camera": {"fov": 0}, "objects": [{"type": "sphere"}]})", "camera.fov"},
        {R"({"render": {"max_bounces": -2}, "objects": [{"type": "sphere"}]})", "render.max_bounces"},
        {R"({"objects": [{"type": "sphere", "material": "nope"}]})", "nope"},
    };
    for (const Case& c : cases) {
        const fs::path scene = writeScene("bad.json", c.text);
        const CliRun r = render("'" + scene.string() + "'" + kSmall + " -o '" + (scratchDir() / "x.png").string() + "'");
        EXPECT_EQ(r.status, 1) << c.text;
        EXPECT_NE(r.err.find(c.expected), std::string::npos) << c.text << "\n--- got:\n" << r.err;
        EXPECT_NE(r.err.find("bad.json"), std::string::npos) << r.err;
    }
    const CliRun missing = render("/nonexistent/scene.json");
    EXPECT_EQ(missing.status, 1);
    EXPECT_NE(missing.err.find("/nonexistent/scene.json"), std::string::npos) << missing.err;
}

TEST(RenderCli, BadCommandLinesAndOutputsFailBeforeRendering) {
    EXPECT_EQ(render("").status, 2);
    EXPECT_EQ(render("scenes/default.json --spp -3").status, 2);
    EXPECT_EQ(render("scenes/default.json --width 0").status, 2);
    EXPECT_EQ(render("scenes/default.json --bogus").status, 2);
    const CliRun bad = render("scenes/default.json --set render.spp=abc -q");
    EXPECT_EQ(bad.status, 1);
    EXPECT_NE(bad.err.find("--set render.spp=abc"), std::string::npos) << bad.err;
    const CliRun unwritable = render("scenes/default.json -o /nonexistent_dir_raylab/x.png");
    EXPECT_EQ(unwritable.status, 1);
    EXPECT_NE(unwritable.err.find("/nonexistent_dir_raylab/x.png: error: cannot write"), std::string::npos)
        << unwritable.err;
    EXPECT_EQ(unwritable.err.find("spp"), std::string::npos) << "it rendered before failing: " << unwritable.err;
    EXPECT_EQ(render("scenes/default.json -o out.tga").status, 1);
}

TEST(RenderCli, DebugViewsWriteRawPerPixelValues) {
    const fs::path exr = scratchDir() / "tri.exr";
    const CliRun r = render("scenes/displaced_terrain.json --width 32 --height 18 --spp 1 --debug-view triangles -o '" +
                            exr.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.err.find("camera rays: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("scene: 3 objects"), std::string::npos) << "the scene statistics: " << r.err;
    const raylab::Image im = raylab::readImage(exr);
    ASSERT_EQ(im.width, 32);
    float most = 0.0f;
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const glm::vec3 c = im.rgb(x, y);
            EXPECT_EQ(c.x, std::floor(c.x)) << "one sample per pixel: whole counts";
            EXPECT_EQ(c.y, std::floor(c.y));
            most = std::max(most, c.y);
        }
    EXPECT_EQ(im.rgb(16, 0).y, 0.0f) << "the sky above the terrain tests no triangle";
    EXPECT_GT(most, 0.0f);
    const CliRun png = render("scenes/default.json --debug-view boxes -o x.png");
    EXPECT_EQ(png.status, 2);
    EXPECT_NE(png.err.find("must be .exr"), std::string::npos) << png.err;
    EXPECT_EQ(render("scenes/default.json --debug-view heat -o x.exr").status, 2);
}

TEST(RenderCli, EveryTracedTableViewIsADebugView) {
    // Parsing stops before rendering with --export-blender: the name is accepted or the exit is 2.
    const std::string py = (scratchDir() / "v.py").string();
    for (const raylab::DebugViewInfo& v : raylab::kDebugViewTable) {
        if (!v.traced) continue;
        SCOPED_TRACE(std::string(v.name));
        const CliRun r = render("scenes/default.json -q --debug-view " + std::string(v.name) + " --export-blender '" + py + "'");
        EXPECT_EQ(r.status, 0) << r.err;
    }
    EXPECT_EQ(render("scenes/default.json -q --debug-view noise --export-blender '" + py + "'").status, 2)
        << "the moment views are drawn by the viewer's display pass, not traced";
}

TEST(RenderCli, SigintWritesThePartialImageAndExits130) {
    const fs::path exr = scratchDir() / "partial.exr";
    int errPipe[2];
    ASSERT_EQ(::pipe(errPipe), 0);
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::dup2(errPipe[1], STDERR_FILENO);
        ::close(errPipe[0]);
        if (::chdir(RAYLAB_SOURCE_DIR) != 0) ::_exit(99);
        ::execl(RAYLAB_RENDER_EXE, RAYLAB_RENDER_EXE, "scenes/default.json", "--width", "32", "--height", "18",
                "--spp", "1000000", "-o", exr.c_str(), static_cast<char*>(nullptr));
        ::_exit(98);
    }
    ::close(errPipe[1]);
    // Wait for the first progress line: rendering has started.
    std::string err;
    char buf[256];
    while (err.find("spp") == std::string::npos) {
        const ssize_t n = ::read(errPipe[0], buf, sizeof buf);
        ASSERT_GT(n, 0) << "raylab-render ended early: " << err;
        err.append(buf, size_t(n));
    }
    ::kill(pid, SIGINT);
    while (::read(errPipe[0], buf, sizeof buf) > 0) {}
    int status = 0;
    ::waitpid(pid, &status, 0);
    ::close(errPipe[0]);
    ASSERT_TRUE(WIFEXITED(status)) << "killed by a signal instead of exiting";
    EXPECT_EQ(WEXITSTATUS(status), 130);
    auto in = OIIO::ImageInput::open(exr.string());
    ASSERT_TRUE(in) << "no partial image";
    const int spp = in->spec().get_int_attribute("raylab:spp");
    EXPECT_GT(spp, 0);
    EXPECT_LT(spp, 1000000);
}

TEST(RenderCli, NonFiniteAndOutOfRangeNumbersAreRefusedAsTheSceneFileWould) {
    const struct {
        const char* args;
        const char* message;
    } cases[] = {
        {"--time nan", "--time: as render.time, must be finite, got nan"},
        {"--time inf", "--time: as render.time, must be finite, got inf"},
        {"--time -1", "--time: as render.time, must be >= 0, got -1"},
        {"--time 1e300", "--time: as render.time, "},
        {"--time 0x10", "--time: expected a number, got '0x10'"},
        {"--spp 0", "--spp: as render.spp, must be >= 1, got 0"},
        {"--width 16385", "--width: as render.width, must be in [1, 16384], got 16385"},
        {"--height -4", "--height: as render.height, must be in [1, 16384], got -4"},
        {"--rpp 2000", "--rpp: as render.rpp, must be in [1, 1024], got 2000"},
        {"--seed 4294967296", "--seed: as render.seed, must be in [0, 4294967295], got 4294967296"},
        {"--seed nan", "--seed: as render.seed, must be finite, got nan"},
    };
    for (const auto& c : cases) {
        const CliRun r = render(std::string("scenes/default.json -q -o /tmp/raylab_never_written.png ") + c.args);
        EXPECT_EQ(r.status, 2) << c.args << "\n" << r.err;
        EXPECT_NE(r.err.find(c.message), std::string::npos) << c.args << "\n" << r.err;
        EXPECT_LT(r.err.size(), 400u) << c.args << ": " << r.err;
    }
    EXPECT_FALSE(fs::exists("/tmp/raylab_never_written.png"));
}

TEST(RenderCli, MalformedMeshesAndImagesExitOneWithALocatedErrorAndNoImage) {
    const fs::path corpus = fs::path(RAYLAB_SOURCE_DIR) / "tests" / "data" / "malformed";
    const fs::path png = scratchDir() / "never.png";
    for (const char* file : {"obj_normal_index_past_end.obj", "gltf_view_names_missing_buffer.gltf",
                             "gltf_accessor_offset_wraps.gltf", "image_png_65535_square.png"}) {
        const bool image = std::string(file).rfind("image_", 0) == 0;
        const fs::path scene = writeScene(
            "malformed.json", image ? R"({ "materials": { "m": { "albedo_texture": ")" + (corpus / file).string() +
                                          R"(" } }, "objects": [ { "material": "m" } ] })"
                                    : R"({ "objects": [ { "type": "mesh", "file": ")" + (corpus / file).string() + R"(" } ] })");
        const CliRun r = render("'" + scene.string() + "' -q -o '" + png.string() + "'");
        EXPECT_EQ(r.status, 1) << file << "\n" << r.err;
        EXPECT_EQ(r.err.rfind(scene.string() + ":1:", 0), 0u) << r.err;
        EXPECT_NE(r.err.find(std::string(image ? "materials.m.albedo_texture: " : "objects[0].file: ") +
                             (corpus / file).string() + ":"),
                  std::string::npos)
            << r.err;
        EXPECT_FALSE(fs::exists(png)) << file;
    }
}
