#include "gl/shader_program.h"

#include <chrono>
#include <utility>
#include <vector>

namespace raylab {
namespace {

// The info log of a shader or a program (the two differ only in their query functions).
template <typename GetIv, typename GetLog>
std::string infoLog(GLuint object, GetIv getIv, GetLog getLog) {
    GLint length = 0;
    getIv(object, GL_INFO_LOG_LENGTH, &length);
    std::string log(static_cast<size_t>(std::max(length, 1)), '\0');
    getLog(object, length, nullptr, log.data());
    return log.c_str();
}

std::string shaderLog(GLuint shader) { return infoLog(shader, glGetShaderiv, glGetShaderInfoLog); }
std::string programLog(GLuint program) { return infoLog(program, glGetProgramiv, glGetProgramInfoLog); }

GLuint compileStage(GLenum stage, const std::filesystem::path& file, const ShaderDefines& defines) {
    const ShaderSource source = assembleShader(file, defines, {shaderDirectory() / "include"});
    GLuint shader = glCreateShader(stage);
    const char* text = source.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        const std::string log = mapShaderLog(shaderLog(shader), source.files);
        glDeleteShader(shader);
        throw ShaderError("GLSL compile error in " + file.string() + ":\n" + log);
    }
    return shader;
}

GLuint link(const std::vector<GLuint>& shaders, const std::string& what) {
    GLuint program = glCreateProgram();
    for (GLuint s : shaders) glAttachShader(program, s);
    glLinkProgram(program);
    for (GLuint s : shaders) glDeleteShader(s);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        const std::string log = programLog(program);
        glDeleteProgram(program);
        throw ShaderError("GLSL link error in " + what + ":\n" + log);
    }
    return program;
}

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
}

} // namespace

ShaderProgram ShaderProgram::graphics(const std::string& vertexEntry,
                                      const std::string& fragmentEntry,
                                      const ShaderDefines& defines) {
    const auto start = Clock::now();
    const auto dir = shaderDirectory();
    GLuint vs = compileStage(GL_VERTEX_SHADER, dir / vertexEntry, defines);
    GLuint fs;
    try {
        fs = compileStage(GL_FRAGMENT_SHADER, dir / fragmentEntry, defines);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    ShaderProgram p;
    p.program_ = link({vs, fs}, vertexEntry + " + " + fragmentEntry);
    p.compileSeconds_ = secondsSince(start);
    return p;
}

ShaderProgram ShaderProgram::compute(const std::string& computeEntry, const ShaderDefines& defines) {
    return computeFromFile(shaderDirectory() / computeEntry, defines);
}

ShaderProgram ShaderProgram::computeFromFile(const std::filesystem::path& file,
                                             const ShaderDefines& defines) {
    const auto start = Clock::now();
    ShaderProgram p;
    p.program_ = link({compileStage(GL_COMPUTE_SHADER, file, defines)}, file.string());
    p.compileSeconds_ = secondsSince(start);
    return p;
}

ShaderProgram::ShaderProgram(ShaderProgram&& other) noexcept
    : program_(std::exchange(other.program_, 0)), compileSeconds_(other.compileSeconds_) {}

ShaderProgram& ShaderProgram::operator=(ShaderProgram&& other) noexcept {
    if (this != &other) {
        if (program_) glDeleteProgram(program_);
        program_ = std::exchange(other.program_, 0);
        compileSeconds_ = other.compileSeconds_;
    }
    return *this;
}

ShaderProgram::~ShaderProgram() {
    if (program_) glDeleteProgram(program_);
}

void ShaderProgram::set(const char* name, int v) const {
    glProgramUniform1i(program_, glGetUniformLocation(program_, name), v);
}
void ShaderProgram::set(const char* name, unsigned v) const {
    glProgramUniform1ui(program_, glGetUniformLocation(program_, name), v);
}
void ShaderProgram::set(const char* name, float v) const {
    glProgramUniform1f(program_, glGetUniformLocation(program_, name), v);
}
void ShaderProgram::set(const char* name, glm::vec2 v) const {
    glProgramUniform2f(program_, glGetUniformLocation(program_, name), v.x, v.y);
}
void ShaderProgram::set(const char* name, glm::vec3 v) const {
    glProgramUniform3f(program_, glGetUniformLocation(program_, name), v.x, v.y, v.z);
}
void ShaderProgram::set(const char* name, glm::ivec2 v) const {
    glProgramUniform2i(program_, glGetUniformLocation(program_, name), v.x, v.y);
}

} // namespace raylab
