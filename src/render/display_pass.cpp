#include "render/display_pass.h"

#include "shaders/include/bindings.glsl"

#include <glad/gl.h>

namespace raylab {

DisplayParams displayParams(int width, int height, DebugView view, const DisplayTransform& transform) {
    DisplayParams p{};
    p.imageSize = glm::ivec2(width, height);
    p.mode = debugViewInfo(view).display;
    p.exposure = transform.exposure;
    p.toneMap = toneMapOp(transform.toneMap);
    return p;
}

DisplayPass::DisplayPass() {
    glCreateVertexArrays(1, &vertexArray_);
    glCreateFramebuffers(1, &framebuffer_);
    glCreateBuffers(1, &paramsBuffer_);
    glNamedBufferStorage(paramsBuffer_, sizeof(DisplayParams), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

DisplayPass::~DisplayPass() {
    glDeleteBuffers(1, &paramsBuffer_);
    glDeleteTextures(1, &texture_);
    glDeleteFramebuffers(1, &framebuffer_);
    glDeleteVertexArrays(1, &vertexArray_);
}

void DisplayPass::reload() {
    program_ = ShaderProgram::graphics("entry/fullscreen.vert", "entry/display.frag");
    compiled_ = true;
}

void DisplayPass::ensureTarget(int width, int height) {
    if (texture_ && width == width_ && height == height_) return;
    glDeleteTextures(1, &texture_);
    glCreateTextures(GL_TEXTURE_2D, 1, &texture_);
    glTextureStorage2D(texture_, 1, GL_RGBA8, width, height);
    glTextureParameteri(texture_, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(texture_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glNamedFramebufferTexture(framebuffer_, GL_COLOR_ATTACHMENT0, texture_, 0);
    width_ = width;
    height_ = height;
}

unsigned DisplayPass::draw(unsigned accumulation, const DisplayParams& params, unsigned moments) {
    if (!compiled_) reload();
    ensureTarget(params.imageSize.x, params.imageSize.y);
    glNamedBufferSubData(paramsBuffer_, 0, sizeof(DisplayParams), &params);
    // texelFetch needs a complete texture: one level, no mipmap filter.
    glTextureParameteri(accumulation, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(accumulation, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, width_, height_);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glBindTextureUnit(BINDING_ACCUM_TEXTURE, accumulation);
    if (moments) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_DEBUG_MOMENTS, moments);
    glBindBufferBase(GL_UNIFORM_BUFFER, BINDING_DISPLAY_PARAMS_UBO, paramsBuffer_);
    glUseProgram(program_.id());
    glBindVertexArray(vertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return texture_;
}

} // namespace raylab
