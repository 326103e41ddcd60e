#pragma once
// A fixture that gives each GL test a current headless OpenGL 4.5 context (OSMesa here).
#include "gl/gl_context.h"

#include <gtest/gtest.h>

#include <memory>

namespace raylab::test {

class GlTest : public ::testing::Test {
protected:
    void SetUp() override {
        try {
            context_ = createHeadlessContext();
        } catch (const std::exception& e) {
            FAIL() << "no OpenGL 4.5 context: " << e.what();
        }
    }
    std::unique_ptr<GlContext> context_;
};

} // namespace raylab::test
