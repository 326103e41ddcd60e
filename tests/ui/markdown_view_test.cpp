// The Markdown view's pictures (ui/panels/markdown_view.h) in a frame without a window: a picture
// is read and framed at the panel's width, and one that cannot be read names the lesson's line.
#include "panels/markdown_view.h"

#include "support/panel_frame_test.h"

#include <filesystem>
#include <fstream>

using namespace raylab;
using namespace raylab::test;
namespace fs = std::filesystem;

namespace {

class MarkdownViewTest : public PanelFrameTest {};


} // namespace

TEST_F(MarkdownViewTest, AMissingPictureShowsWhereTheLessonAsksForIt) {
    const Lesson lesson = loadLesson(fs::path(RAYLAB_SOURCE_DIR) / "lessons/05-ray-box-bvh.md");
    ASSERT_FALSE(lesson.pictures.empty());
    Lesson moved = lesson;
    moved.file = fs::path(RAYLAB_SOURCE_DIR) / "tests/data/05-ray-box-bvh.md";   // no pictures/ folder there
    const std::string source = lesson.pictures[0].source;
    const std::string text = windowText([&] {
        ImGui::Begin("md");
        ui::drawMarkdown("Text before.\n\n![the slab test](" + source + ")\n\nText after.\n", &moved);
        ImGui::End();
    });
    EXPECT_NE(text.find(moved.file.string() + ":" + std::to_string(lesson.pictures[0].line) + ": cannot show the picture '" + source + "'"),
              std::string::npos) << text;
    EXPECT_NE(text.find("after."), std::string::npos) << "the rest of the text is still drawn: " << text;
}

TEST_F(MarkdownViewTest, APictureIsFramedAtThePanelsWidthWithItsAltText) {
    const Lesson lesson = loadLesson(fs::path(RAYLAB_SOURCE_DIR) / "lessons/05-ray-box-bvh.md");
    const std::string source = lesson.pictures.at(0).source;
    float height = 0.0f;
    const std::string text = windowText([&] {
        ImGui::SetNextWindowSize(ImVec2(400, 600));
        ImGui::Begin("md");
        const float top = ImGui::GetCursorPosY();
        const float width = ImGui::GetContentRegionAvail().x;
        ui::drawMarkdown("![the slab test](" + source + ")\n", &lesson);
        height = (ImGui::GetCursorPosY() - ImGui::GetStyle().ItemSpacing.y - top) / width;
        ImGui::End();
    });
    EXPECT_NE(text.find("[picture: the slab test]"), std::string::npos) << text;
    EXPECT_EQ(text.find("cannot show"), std::string::npos) << text;
    EXPECT_NEAR(height, 270.0f / 480.0f, 0.01f) << "the picture keeps its aspect at the panel's width";
}
