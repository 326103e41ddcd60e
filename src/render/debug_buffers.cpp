#include "render/debug_buffers.h"

#include "shaders/include/bindings.glsl"

#include <glad/gl.h>

namespace raylab {

DebugBuffers::DebugBuffers() {
    glCreateBuffers(1, &heatMax_);
    glNamedBufferStorage(heatMax_, 2 * sizeof(GLuint), nullptr, GL_DYNAMIC_STORAGE_BIT);
}

DebugBuffers::~DebugBuffers() {
    glDeleteBuffers(1, &moments_);
    glDeleteBuffers(1, &heatMax_);
}

void DebugBuffers::restart(int width, int height) {
    const GLsizeiptr bytes = GLsizeiptr(width) * height * GLsizeiptr(sizeof(glm::vec4));
    GLint64 have = 0;
    if (moments_) glGetNamedBufferParameteri64v(moments_, GL_BUFFER_SIZE, &have);
    if (have != bytes) {
        glDeleteBuffers(1, &moments_);
        moments_ = 0;
        if (bytes > 0) {
            glCreateBuffers(1, &moments_);
            glNamedBufferStorage(moments_, bytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
        }
    }
    const float zero = 0.0f;
    if (moments_) glClearNamedBufferData(moments_, GL_R32F, GL_RED, GL_FLOAT, &zero);
    const GLuint none = 0;
    glClearNamedBufferData(heatMax_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
}

void DebugBuffers::bind() const {
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_DEBUG_MOMENTS, moments_);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_DEBUG_HEAT_MAX, heatMax_);
}

glm::uvec2 DebugBuffers::heatMax() const {
    GLuint most[2] = {0, 0};
    glGetNamedBufferSubData(heatMax_, 0, sizeof(most), most);
    return {most[0], most[1]};
}

void setTracedView(const ShaderProgram& program, DebugView view, int bounce) {
    program.set("uDebugView", int(view));
    program.set("uDebugBounce", bounce);
}

} // namespace raylab
