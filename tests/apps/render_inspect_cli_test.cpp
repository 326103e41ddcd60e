// raylab-render --inspect X,Y --inspect-out FILE: the pixel path inspector from the command line.
#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

struct CliRun {
    int status = -1;
    std::string err;
};

fs::path scratch() {
    fs::path d = fs::temp_directory_path() / ("raylab_inspect_cli_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}

CliRun renderCli(const std::string& args) {
    const fs::path err = scratch() / "err.txt";
    const std::string cmd = std::string("cd '") + RAYLAB_SOURCE_DIR + "' && '" + RAYLAB_RENDER_EXE + "' " + args +
                            " > /dev/null 2> '" + err.string() + "'";
    const int raw = std::system(cmd.c_str());
    std::ifstream in(err);
    std::stringstream ss;
    ss << in.rdbuf();
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, ss.str()};
}

TEST(RenderInspectCli, WritesJsonAndCsv) {
    const fs::path json = scratch() / "path.json", csv = scratch() / "path.csv";
    CliRun r = renderCli("scenes/lesson_one_sphere.json --width 48 --height 32 --inspect 24,20 --inspect-paths 3 "
                      "--inspect-out '" + json.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    std::ifstream in(json);
    const nlohmann::json j = nlohmann::json::parse(in);
    ASSERT_EQ(j.size(), 3u);
    EXPECT_EQ(j[0]["pixel"][0], 24);
    EXPECT_EQ(j[0]["pixel"][1], 20);
    EXPECT_EQ(j[2]["sample"], 2);
    EXPECT_FALSE(j[0]["bounces"].empty());
    r = renderCli("scenes/lesson_one_sphere.json --width 48 --height 32 --inspect 24,20 --inspect-out '" +
                  csv.string() + "'");
    ASSERT_EQ(r.status, 0) << r.err;
    std::ifstream c(csv);
    std::string header;
    std::getline(c, header);
    EXPECT_EQ(header.rfind("path,sample,bounce,", 0), 0u) << header;
}

TEST(RenderInspectCli, BadPixelIsACommandLineError) {
    CliRun r = renderCli("scenes/lesson_one_sphere.json --width 48 --height 32 --inspect 48,0");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("outside"), std::string::npos) << r.err;
    r = renderCli("scenes/lesson_one_sphere.json --inspect 3");
    EXPECT_EQ(r.status, 2);
    EXPECT_NE(r.err.find("X,Y"), std::string::npos) << r.err;
    r = renderCli("scenes/lesson_one_sphere.json --width 48 --height 32 --inspect 1,1 --inspect-out "
                  "'" + (scratch() / "p.txt").string() + "'");
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("p.txt"), std::string::npos) << r.err;
}

} // namespace
