#pragma once
// Assembles a GLSL entry point with its includes into one source string. #include "file" is
// resolved relative to the including file, then in the include directories; each file is
// included once. Host defines go right after #version. A define whose value is a quoted path is
// a file define: GLSL sees it as 1, and `#include NAME` includes that file (an include of a define
// the host did not set includes nothing, as it stands in that define's #ifdef). Numeric #line directives (GLSL rejects
// file names there) point back to a table of files, so compiler messages can name file:line.
// The C++ half of a shared header (the lines an `#ifdef __cplusplus` keeps) arrives blank.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace raylab {

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;

struct ShaderSource {
    std::string text;                            // what goes to glShaderSource
    std::vector<std::filesystem::path> files;    // source-string number → file
};

// A shader that could not be assembled, compiled or linked; the message names file:line.
class ShaderError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

ShaderSource assembleShader(const std::filesystem::path& entryFile, const ShaderDefines& defines = {},
                            const std::vector<std::filesystem::path>& includeDirs = {});

// Rewrites compiler log locations "N:LINE(COL)" (Mesa) or "N(LINE)" (NVIDIA) as "file:LINE:COL".
std::string mapShaderLog(const std::string& log, const std::vector<std::filesystem::path>& files);

// Where shaders live: $RAYLAB_SHADER_DIR, else <exe>/../share/raylab/shaders, else the source tree.
std::filesystem::path shaderDirectory();

} // namespace raylab
