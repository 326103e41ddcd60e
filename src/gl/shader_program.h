#pragma once
// A linked GL program built from entry-point files; errors come back as ShaderError naming
// file:line of the GLSL that failed. Requires a current context.
#include "gl/shader_source.h"

#include <glad/gl.h>
#include <glm/glm.hpp>

#include <string>

namespace raylab {

class ShaderProgram {
public:
    ShaderProgram() = default;
    // Vertex + fragment, or a compute program alone. Paths are relative to shaderDirectory().
    static ShaderProgram graphics(const std::string& vertexEntry, const std::string& fragmentEntry,
                                  const ShaderDefines& defines = {});
    static ShaderProgram compute(const std::string& computeEntry, const ShaderDefines& defines = {});
    // From an absolute or relative path, for tests of error reporting.
    static ShaderProgram computeFromFile(const std::filesystem::path& file,
                                         const ShaderDefines& defines = {});

    ShaderProgram(ShaderProgram&& other) noexcept;
    ShaderProgram& operator=(ShaderProgram&& other) noexcept;
    ~ShaderProgram();

    GLuint id() const { return program_; }
    double compileSeconds() const { return compileSeconds_; }

    // Uniform setters; a uniform the compiler removed is silently skipped (location -1).
    void set(const char* name, int v) const;
    void set(const char* name, unsigned v) const;
    void set(const char* name, float v) const;
    void set(const char* name, glm::vec2 v) const;
    void set(const char* name, glm::vec3 v) const;
    void set(const char* name, glm::ivec2 v) const;

private:
    GLuint program_ = 0;
    double compileSeconds_ = 0.0;
};

} // namespace raylab
