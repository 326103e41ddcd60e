// The value under the cursor: with the mouse over the image and the tooltip on, the Viewport
// shows the pixel's coordinates, its accumulated value and what is seen there (ImGui frames
// without a window, support/panel_frame_test.h).
#include "app/view_geometry.h"
#include "support/panel_frame_test.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <cstdio>
#include <string>
#include <vector>

namespace raylab::ui {
namespace {

class PixelTooltipTest : public test::PanelFrameTest {
protected:
    // Traces the 32 x 18 image to its target, so the values the tooltip reads stay put.
    void SetUp() override {
        PanelFrameTest::SetUp();
        ASSERT_TRUE(viewer->document().set("render.spp", "4"));
        for (int i = 0; i < 10000 && !viewer->converged(); ++i) viewer->update(0.01);
        ASSERT_TRUE(viewer->converged());
        frame();   // lays the image out: ui.image
        ASSERT_TRUE(ui.image.valid());
    }
    // Puts the mouse on the centre of image pixel (x, y) and lets ImGui see it hover there.
    void hover(int x, int y) {
        ImGui::GetIO().MousePos = ImVec2(ui.image.x + (float(x) + 0.5f) * ui.image.width / float(viewer->imageWidth()),
                                         ui.image.y + (float(y) + 0.5f) * ui.image.height / float(viewer->imageHeight()));
        frame();
    }
    std::string viewportText() {
        return windowText([&] { drawViewport(*viewer, ui); });
    }
    // The tooltip's lines in the frame's text: the one from "pixel (" on and the two after it.
    static std::vector<std::string> tooltip(const std::string& text) {
        std::vector<std::string> lines;
        std::size_t at = text.find("pixel (");
        while (at != std::string::npos && lines.size() < 3) {
            const std::size_t end = text.find('\n', at);
            lines.push_back(text.substr(at, end == std::string::npos ? std::string::npos : end - at));
            at = end == std::string::npos ? end : end + 1;
        }
        lines.resize(3);
        return lines;
    }
    static std::string format(const char* fmt, glm::vec3 v) {
        char text[160];
        std::snprintf(text, sizeof text, fmt, double(v.x), double(v.y), double(v.z));
        return text;
    }
};

TEST_F(PixelTooltipTest, ShowsThePixelsValueAndWhatIsSeenThere) {
    // Independent of the tooltip's own read-back: the whole image, top row first.
    const Image image = viewer->tracer()->readImage();
    const Scene& s = viewer->scene();
    int objects = 0, sky = 0;
    for (auto [x, y] : {std::pair{16, 14}, std::pair{20, 9}, std::pair{3, 1}, std::pair{31, 17}}) {
        SCOPED_TRACE(std::to_string(x) + ", " + std::to_string(y));
        hover(x, y);
        const std::string text = viewportText();
        const std::vector<std::string> t = tooltip(text);
        EXPECT_EQ(t[0], "pixel (" + std::to_string(x) + ", " + std::to_string(y) + ")") << text;
        EXPECT_EQ(t[1], format("beauty: %.4g %.4g %.4g", image.rgb(x, y)));
        const auto seen = pickObject(s, 32, 18, ImagePoint{float(x) + 0.5f, float(y) + 0.5f});
        if (seen) {
            ++objects;
            // The default scene has spheres only: object i is sphere i.
            ASSERT_LT(std::size_t(*seen), s.spheres.size());
            const int m = s.spheres[std::size_t(*seen)].material;
            EXPECT_EQ(t[2], "object " + std::to_string(*seen) + " (sphere " + std::to_string(*seen) + "), material " +
                                std::to_string(m) + " '" + s.materials[std::size_t(m)].name + "'");
        } else {
            ++sky;
            EXPECT_EQ(t[2], "sky");
        }
    }
    EXPECT_GT(objects, 0);
    EXPECT_GT(sky, 0) << "choose pixels that show both";
}

TEST_F(PixelTooltipTest, NamesTheDebugViewItReads) {
    viewer->setDebugView(DebugView::Normals);
    for (int i = 0; i < 10000 && !viewer->converged(); ++i) viewer->update(0.01);
    const Image normals = viewer->tracer()->readImage();
    hover(16, 14);
    EXPECT_EQ(tooltip(viewportText())[1], format("normals: %.4g %.4g %.4g", normals.rgb(16, 14)));
}

TEST_F(PixelTooltipTest, NoneWhenOffOrOutsideTheImage) {
    hover(16, 14);
    ASSERT_NE(viewportText().find("pixel ("), std::string::npos);
    ui.pixelTooltip = false;
    EXPECT_EQ(viewportText().find("pixel ("), std::string::npos);
    ui.pixelTooltip = true;
    ImGui::GetIO().MousePos = ImVec2(ui.image.x - 20.0f, ui.image.y + 5.0f);
    frame();
    EXPECT_EQ(viewportText().find("pixel ("), std::string::npos);
}

} // namespace
} // namespace raylab::ui
