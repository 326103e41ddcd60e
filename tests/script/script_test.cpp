// The automation script (src/script): commands parse with their arguments, comments and blank
// lines are skipped, and every kind of mistake is reported as FILE:LINE before anything runs.
#include "render/debug_views.h"
#include "script/script.h"

#include <gtest/gtest.h>

#include <string>

using namespace raylab;

namespace {

// "beauty, normals, ...": every view of the table, as the error message lists them.
std::string debugViewList() {
    std::string list;
    for (std::string_view v : scriptDebugViews()) list += (list.empty() ? "" : ", ") + std::string(v);
    return list;
}

std::string errorOf(const std::string& text, int firstLine = 1) {
    try {
        parseScript(text, "s.txt", firstLine);
    } catch (const ScriptError& e) {
        return e.what();
    }
    return "<no error>";
}

} // namespace

TEST(Script, ParsesEveryCommand) {
    const auto cmds = parseScript("# a comment\n"
                                  "open scenes/default.json\n"
                                  "\n"
                                  "set materials.red.albedo [1, 0, 0]   # trailing comment\n"
                                  "click 10 20\npick 3 4\nselect 2\ndebug-view normals\n"
                                  "overlay boxes on\noverlay selected off\nscale 0.5\n"
                                  "pause\nresume\nreset\nwait-spp 16\nwait-frames 3\n"
                                  "screenshot a.png\nexport b.exr\nsave c.json\nwindow 800 600\nquit\n",
                                  "s.txt");
    ASSERT_EQ(cmds.size(), 19u);
    EXPECT_EQ(cmds[0].name, "open");
    EXPECT_EQ(cmds[0].line, 2);
    EXPECT_EQ(cmds[1].name, "set");
    ASSERT_EQ(cmds[1].args.size(), 2u);
    EXPECT_EQ(cmds[1].args[0], "materials.red.albedo");
    EXPECT_EQ(cmds[1].args[1], "[1, 0, 0]");   // the rest of the line, spaces kept, comment dropped
    EXPECT_EQ(cmds[1].line, 4);
    EXPECT_EQ(cmds[18].name, "quit");
    EXPECT_EQ(cmds[1].text(), "line 4: set materials.red.albedo [1, 0, 0]");
}

TEST(Script, LinesCountFromFirstLine) {
    const auto cmds = parseScript("reset\n\nwait-spp 4\n", "lesson.md", 41);
    ASSERT_EQ(cmds.size(), 2u);
    EXPECT_EQ(cmds[0].line, 41);
    EXPECT_EQ(cmds[1].line, 43);
    EXPECT_EQ(errorOf("reset\nbogus\n", 41), "s.txt:42: error: unknown command 'bogus'");
}

TEST(Script, RejectsMistakesWithFileAndLine) {
    EXPECT_EQ(errorOf("reset\nrender now\n"), "s.txt:2: error: unknown command 'render'");
    EXPECT_EQ(errorOf("open\n"), "s.txt:1: error: open takes 1 argument(s), got 0");
    EXPECT_EQ(errorOf("pause now\n"), "s.txt:1: error: pause takes 0 argument(s), got 1");
    EXPECT_EQ(errorOf("set camera.fov\n"), "s.txt:1: error: set needs KEY VALUE");
    EXPECT_EQ(errorOf("wait-spp lots\n"), "s.txt:1: error: wait-spp: 'lots' is not a number");
    EXPECT_EQ(errorOf("window 800 tall\n"), "s.txt:1: error: window: 'tall' is not a number");
    EXPECT_EQ(errorOf("debug-view heat\n"), "s.txt:1: error: unknown debug view 'heat' (" + debugViewList() + ")");
    EXPECT_EQ(errorOf("overlay boxes maybe\n"), "s.txt:1: error: overlay takes boxes|selected|paths|bvh|mesh-bvh|lights on|off");
    EXPECT_EQ(errorOf("overlay grid on\n"), "s.txt:1: error: overlay takes boxes|selected|paths|bvh|mesh-bvh|lights on|off");
    EXPECT_EQ(errorOf("select-light 1\noverlay lights on\n"), "<no error>");
    EXPECT_EQ(errorOf("select-light sun\n"), "s.txt:1: error: select-light: 'sun' is not a number");
}

TEST(Script, InspectorCommands) {
    EXPECT_EQ(errorOf("inspect 10 20\ninspect 10 20 4\noverlay paths off\nexplore 0\nexplore 1 2\n"
                      "inspect-export p.json\npanel inspector on\npanel brdf-explorer off\n"),
              "<no error>");
    EXPECT_EQ(errorOf("inspect 10\n"), "s.txt:1: error: inspect takes 2 or 3 argument(s), got 1");
    EXPECT_EQ(errorOf("inspect 10 y\n"), "s.txt:1: error: inspect: 'y' is not a number");
    EXPECT_EQ(errorOf("explore first\n"), "s.txt:1: error: explore: 'first' is not a number");
    EXPECT_EQ(errorOf("panel lesson on\n"), "s.txt:1: error: panel takes inspector|brdf-explorer on|off");
}

TEST(Script, EveryDebugViewNameParses) {
    ASSERT_EQ(scriptDebugViews().size(), std::size(kDebugViewTable));
    for (std::string_view v : scriptDebugViews())
        EXPECT_EQ(errorOf("debug-view " + std::string(v) + "\n"), "<no error>") << v;
}

TEST(Script, InspectionCommandsCheckTheirArguments) {
    EXPECT_EQ(errorOf("focus 10 20\nfocus-mode on\nbvh-depth 3\nheat-scale auto\nheat-scale 40\noverlay bvh on\n"
                      "overlay mesh-bvh off\n"),
              "<no error>");
    EXPECT_EQ(errorOf("focus 10\n"), "s.txt:1: error: focus takes 2 argument(s), got 1");
    EXPECT_EQ(errorOf("focus here there\n"), "s.txt:1: error: focus: 'here' is not a number");
    EXPECT_EQ(errorOf("focus-mode maybe\n"), "s.txt:1: error: focus-mode takes on|off");
    EXPECT_EQ(errorOf("bvh-depth deep\n"), "s.txt:1: error: bvh-depth: 'deep' is not a number");
    EXPECT_EQ(errorOf("heat-scale 0\n"), "s.txt:1: error: heat-scale takes auto or a count > 0");
    EXPECT_EQ(errorOf("heat-scale hot\n"), "s.txt:1: error: heat-scale takes auto or a count > 0");
}

TEST(Script, MissingFileIsAnError) {
    try {
        loadScript("/nonexistent/raylab.script");
        FAIL() << "no error";
    } catch (const ScriptError& e) {
        EXPECT_EQ(std::string(e.what()), "/nonexistent/raylab.script: error: cannot open the script");
    }
}

TEST(Script, ParsesTheTeachingCommands) {
    const auto cmds = parseScript("bounce-step 2\nbounce-step next\nbounce-step off\nstage lambert\nsplit time\n"
                                  "split-a render.nee false\nsplit-b materials.red.albedo [1, 0, 0]\nsplit-divider 0.3\n"
                                  "ui-scale 1.5\nkey page-down\nkey page-up\nlesson lessons/01-rendering-equation.md\n"
                                  "lesson-step 2\nself-test\nsplit off\nteach classroom\n",
                                  "s.txt");
    ASSERT_EQ(cmds.size(), 16u);
    EXPECT_EQ(errorOf("teach stats\n"), "s.txt:1: error: teach takes lesson, classroom, self-test or off");
    EXPECT_EQ(cmds[6].args[1], "[1, 0, 0]");   // split-b takes the rest of the line, as set
    EXPECT_EQ(errorOf("bounce-step many\n"), "s.txt:1: error: bounce-step takes a number, next or off");
    EXPECT_EQ(errorOf("stage phong\n"), "s.txt:1: error: unknown stage 'phong' (primary, emission, lambert, ggx, textures, full)");
    EXPECT_EQ(errorOf("split halves\n"), "s.txt:1: error: split takes samples, time or off");
    EXPECT_EQ(errorOf("split-a render.nee\n"), "s.txt:1: error: split-a needs KEY VALUE");
    EXPECT_EQ(errorOf("key escape\n"), "s.txt:1: error: key takes page-down, page-up, space, r, f5, f9, f12, f1, f2, ctrl+s, ctrl+=, ctrl+-, ctrl+0, "
              "w, s, a, d, q, e, left, right, up or down");
    EXPECT_EQ(errorOf("ui-scale big\n"), "s.txt:1: error: ui-scale: 'big' is not a number");
    EXPECT_EQ(errorOf("lesson-step two\n"), "s.txt:1: error: lesson-step: 'two' is not a number");
}

TEST(Script, KeysAndDrops) {
    for (std::string_view k : scriptKeys()) EXPECT_EQ(errorOf("key " + std::string(k) + "\n"), "<no error>") << k;
    EXPECT_EQ(errorOf("key F9\n"), "s.txt:1: error: key takes page-down, page-up, space, r, f5, f9, f12, f1, f2, ctrl+s, ctrl+=, ctrl+-, ctrl+0, "
              "w, s, a, d, q, e, left, right, up or down");
    const auto held = parseScript("key w 5\nkey left\n", "s.txt");
    EXPECT_EQ(held.at(0).args, (std::vector<std::string>{"w", "5"}));
    EXPECT_EQ(held.at(1).args.size(), 1u);
    EXPECT_EQ(errorOf("key w 0\n"), "s.txt:1: error: key: '0' is not a count of frames (a whole number >= 1)");
    EXPECT_EQ(errorOf("key w 1.5\n"), "s.txt:1: error: key: '1.5' is not a count of frames (a whole number >= 1)");
    EXPECT_EQ(errorOf("key w 2 3\n"), "s.txt:1: error: key takes 1 or 2 argument(s), got 3");
    EXPECT_EQ(parseScript("drop /tmp/scene.json\n", "s.txt").at(0).args.at(0), "/tmp/scene.json");
    EXPECT_EQ(errorOf("drop\n"), "s.txt:1: error: drop takes 1 argument(s), got 0");
    EXPECT_EQ(errorOf("drop a.json b.json\n"), "s.txt:1: error: drop takes 1 argument(s), got 2");
}

TEST(Script, ExpectAndHoldParse) {
    const auto cmds = parseScript("expect materials.ball.albedo [0.9, 0.15, 0.1]\nhold\nexpect debug-view noise\n"
                                  "expect scale 0.5\nexpect bounce-step off\n",
                                  "s.txt");
    ASSERT_EQ(cmds.size(), 5u);
    EXPECT_EQ(cmds[0].args.at(1), "[0.9, 0.15, 0.1]");   // the rest of the line, as set
    EXPECT_TRUE(cmds[1].args.empty());
    EXPECT_EQ(errorOf("expect render.spp\n"), "s.txt:1: error: expect needs KEY VALUE");
    EXPECT_EQ(errorOf("hold on\n"), "s.txt:1: error: hold takes 0 argument(s), got 1");
    EXPECT_EQ(errorOf("expect debug-view heat\n"), "s.txt:1: error: unknown debug view 'heat' (" + debugViewList() + ")");
    EXPECT_EQ(errorOf("expect scale half\n"), "s.txt:1: error: expect scale takes a number");
    EXPECT_EQ(errorOf("expect bounce-step all\n"), "s.txt:1: error: expect bounce-step takes a number or off");
}
