// raylab-render --inspect X,Y --inspect-out FILE: the pixel path inspector from the command line.
#include "support/render_cli.h"

#include <nlohmann/json.hpp>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;

namespace {

using raylab::test::CliRun;

fs::path scratch() { return raylab::test::scratchDir("raylab_inspect_cli"); }

CliRun renderCli(const std::string& args) { return raylab::test::runRender(args, scratch()); }

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
