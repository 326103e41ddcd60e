// raylab-render with a sky map it cannot read: a located error at sky.map and exit status 1 (a
// scene error), never 3 (no OpenGL or a shader failure), and no image written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

TEST(RenderSkyMapCli, AGarbageSkyMapExitsOneWithItsPlace) {
    const fs::path dir = fs::temp_directory_path() / ("raylab_sky_map_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "garbage.hdr") << "#?RADIANCE\nnot really\n";
    std::ofstream(dir / "scene.json") << "{ \"sky\": { \"type\": \"map\", \"map\": \"garbage.hdr\" },\n"
                                         "  \"objects\": [ {} ] }\n";
    const fs::path image = dir / "out.png";
    const std::string cmd = std::string("'") + RAYLAB_RENDER_EXE + "' '" + (dir / "scene.json").string() + "' -o '" +
                            image.string() + "' --width 8 --height 8 --spp 1 -q 2> '" + (dir / "err.txt").string() + "'";
    const int raw = std::system(cmd.c_str());
    ASSERT_TRUE(WIFEXITED(raw));
    EXPECT_EQ(WEXITSTATUS(raw), 1);
    std::ifstream in(dir / "err.txt");
    std::stringstream err;
    err << in.rdbuf();
    EXPECT_EQ(err.str().rfind((dir / "scene.json").string() + ":1:34: error: sky.map: " + (dir / "garbage.hdr").string() +
                                  ": cannot read: ",
                              0),
              0u)
        << err.str();
    EXPECT_FALSE(fs::exists(image));
    fs::remove_all(dir);
}
