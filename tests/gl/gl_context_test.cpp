#include "gl/gl_context.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

using namespace raylab;

namespace {

void expectGl45Core() {
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    EXPECT_GE(major * 10 + minor, 45);
    EXPECT_TRUE(profile & GL_CONTEXT_CORE_PROFILE_BIT);
    // Entry points that libOSMesa does not export as symbols must come through the loader.
    EXPECT_NE(glad_glDispatchCompute, nullptr);
    EXPECT_NE(glad_glCreateTextures, nullptr);
}

} // namespace

TEST(GlContext, OSMesaGivesAnOpenGL45CoreContext) {
    auto context = createOSMesaContext();
    expectGl45Core();
    EXPECT_EQ(context->description().rfind("osmesa | ", 0), 0u) << context->description();
}

TEST(GlContext, EglGivesAnOpenGL45CoreContextWhenAvailable) {
    std::unique_ptr<GlContext> context;
    try {
        context = createEglContext();
    } catch (const std::exception& e) {
        GTEST_SKIP() << "no EGL here: " << e.what();
    }
    expectGl45Core();
    EXPECT_EQ(context->description().rfind("egl-", 0), 0u) << context->description();
}

TEST(GlContext, BackendNamesParseAndUnknownNamesFail) {
    EXPECT_EQ(parseGlBackend("osmesa"), GlBackend::OSMesa);
    EXPECT_EQ(parseGlBackend("egl"), GlBackend::Egl);
    EXPECT_EQ(parseGlBackend("auto"), GlBackend::Auto);
    EXPECT_THROW(parseGlBackend("vulkan"), std::invalid_argument);
}
