#include "app/script.h"

#include <gtest/gtest.h>

namespace raylab::ui {
namespace {

TEST(Script, ParsesCommandsCommentsAndSetValuesWithSpaces) {
    const auto cmds = parseScript("# a test\nopen scenes/default.json\n\nset materials.red.albedo [1, 0, 0]  # red\n"
                                  "click 10 20\ndebug-view normals\noverlay boxes on\nwait-spp 8\nquit\n",
                                  "t.txt");
    ASSERT_EQ(cmds.size(), 7u);
    EXPECT_EQ(cmds[0].name, "open");
    EXPECT_EQ(cmds[1].line, 4);
    EXPECT_EQ(cmds[1].args, (std::vector<std::string>{"materials.red.albedo", "[1, 0, 0]"}));
    EXPECT_EQ(cmds[2].args, (std::vector<std::string>{"10", "20"}));
    EXPECT_EQ(cmds[6].name, "quit");
}

TEST(Script, ErrorsNameFileAndLine) {
    auto error = [](const std::string& text) {
        try {
            parseScript(text, "s.txt");
        } catch (const ScriptError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_EQ(error("open a\nfly 1 2\n"), "s.txt:2: error: unknown command 'fly'");
    EXPECT_EQ(error("click 1\n"), "s.txt:1: error: click takes 2 argument(s), got 1");
    EXPECT_EQ(error("\n\nwait-spp many\n"), "s.txt:3: error: wait-spp: 'many' is not a number");
    EXPECT_NE(error("debug-view bvh\n").find("s.txt:1: error: unknown debug view 'bvh'"), std::string::npos);
    EXPECT_EQ(error("overlay boxes maybe\n"), "s.txt:1: error: overlay takes boxes|selected on|off");
    EXPECT_EQ(error("set camera.fov\n"), "s.txt:1: error: set needs KEY VALUE");
}

} // namespace
} // namespace raylab::ui
