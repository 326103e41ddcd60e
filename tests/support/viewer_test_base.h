#pragma once
// A GL test with a viewer on the headless context: openSmall() loads a scene file of scenes/ and
// traces it at a small size (what most viewer tests need first).
#include "app/viewer.h"
#include "render/render_helpers.h"
#include "support/gl_test.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace raylab::test {

class ViewerTestBase : public GlTest {
protected:
    // Opens scenes/`scene` in the viewer (made on first use) at width × height.
    void openSmall(const std::string& scene, int width, int height) {
        if (!viewer) viewer = std::make_unique<ui::Viewer>(log);
        ASSERT_TRUE(viewer->openScene(scenePath(scene))) << viewer->document().lastError();
        ASSERT_TRUE(viewer->document().set("render.width", std::to_string(width)));
        ASSERT_TRUE(viewer->document().set("render.height", std::to_string(height)));
    }
    ui::Log log{false};
    std::unique_ptr<ui::Viewer> viewer;
};

} // namespace raylab::test
