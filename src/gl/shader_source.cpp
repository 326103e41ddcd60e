#include "gl/shader_source.h"

#include "io/resource_directory.h"

#include <cctype>
#include <cstdlib>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string_view>

namespace raylab {
namespace fs = std::filesystem;
namespace {

bool isQuotedPath(const std::string& v) { return v.size() >= 2 && v.front() == '"' && v.back() == '"'; }

struct Assembler {
    ShaderDefines hostDefines;
    std::vector<fs::path> includeDirs;
    std::vector<fs::path> files;
    std::set<fs::path> included;
    std::vector<fs::path> stack;   // for include cycles
    std::ostringstream out;

    int fileIndex(const fs::path& p) {
        for (size_t i = 0; i < files.size(); ++i)
            if (files[i] == p) return static_cast<int>(i);
        files.push_back(p);
        return static_cast<int>(files.size() - 1);
    }

    // The file of a define whose value is a quoted path (`#include NAME` includes it), if any.
    const std::string* fileDefine(const std::string& name) const {
        for (const auto& [n, v] : hostDefines)
            if (n == name && isQuotedPath(v)) return &v;
        return nullptr;
    }

    static std::string readFile(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        if (!in) throw ShaderError(p.string() + ": error: cannot read shader file");
        std::ostringstream ss;
        ss << in.rdbuf();
        return ss.str();
    }

    fs::path resolve(const std::string& name, const fs::path& from, int line) const {
        fs::path candidate = from.parent_path() / name;
        if (fs::exists(candidate)) return fs::weakly_canonical(candidate);
        for (const auto& dir : includeDirs)
            if (fs::exists(dir / name)) return fs::weakly_canonical(dir / name);
        throw ShaderError(from.string() + ":" + std::to_string(line) +
                          ": error: cannot find included file \"" + name + "\"");
    }

    fs::path resolveFileDefine(const std::string& quoted, const fs::path& from, int line) const {
        const fs::path p = quoted.substr(1, quoted.size() - 2);
        if (fs::exists(p)) return fs::weakly_canonical(p);
        throw ShaderError(from.string() + ":" + std::to_string(line) + ": error: cannot find included file " + quoted);
    }

    // The first word of a preprocessor line ("include", "ifdef", …), or "" for any other line.
    static std::string_view directive(std::string_view line) {
        size_t i = line.find_first_not_of(" \t");
        if (i == std::string_view::npos || line[i] != '#') return {};
        i = line.find_first_not_of(" \t", i + 1);
        if (i == std::string_view::npos) return {};
        size_t end = i;
        while (end < line.size() && std::isalpha(static_cast<unsigned char>(line[end]))) ++end;
        return line.substr(i, end - i);
    }

    // Emits one file. For the entry file, defines are placed after its #version line.
    void emit(const fs::path& file, const ShaderDefines* defines) {
        const int index = fileIndex(file);
        stack.push_back(file);
        std::istringstream in(readFile(file));
        static const std::regex includeRe(R"(^\s*#\s*include\s*"([^"]+)\"\s*(//.*)?$)");
        static const std::regex macroIncludeRe(R"(^\s*#\s*include\s+([A-Za-z_][A-Za-z0-9_]*)\s*(//.*)?$)");
        static const std::regex versionRe(R"(^\s*#\s*version\b.*)");
        static const std::regex cplusplusRe(R"(^\s*#\s*ifdef\s+__cplusplus\b.*)");
        std::string line;
        int lineNo = 0;
        bool versionSeen = defines == nullptr;
        // Depth of the #if blocks open inside the C++ half of an `#ifdef __cplusplus` (0: outside
        // one). GLSL never defines __cplusplus, so that half reaches the compiler as blank lines:
        // Mesa looks a source up in its shader cache before preprocessing only when the text has
        // no "#include", which the shared headers' C++ halves have (<glm/glm.hpp>).
        int cplusplusDepth = 0;
        if (defines == nullptr) out << "#line 1 " << index << "\n";
        while (std::getline(in, line)) {
            ++lineNo;
            if (!line.empty() && line.back() == '\r') line.pop_back();
            const std::string_view word = directive(line);
            if (cplusplusDepth > 0) {
                if (word == "if" || word == "ifdef" || word == "ifndef") ++cplusplusDepth;
                else if (word == "endif" || ((word == "else" || word == "elif") && cplusplusDepth == 1)) --cplusplusDepth;
                if (cplusplusDepth > 0) {
                    out << "\n";
                    continue;
                }
                out << line << "\n";   // the #else, #elif or #endif that ends the C++ half
                continue;
            }
            if (word.empty()) {   // most lines: no directive, nothing to match
                out << line << "\n";
                continue;
            }
            std::smatch m;
            if (word == "ifdef" && std::regex_match(line, cplusplusRe)) {
                cplusplusDepth = 1;
                out << line << "\n";
                continue;
            }
            if (!versionSeen && std::regex_match(line, versionRe)) {
                out << line << "\n";
                // GLSL has no strings: a file define is only switched on; `#include NAME` takes its path.
                for (const auto& [name, value] : *defines)
                    out << "#define " << name << " " << (isQuotedPath(value) ? "1" : value) << "\n";
                out << "#line " << lineNo + 1 << " " << index << "\n";
                versionSeen = true;
                continue;
            }
            const bool macroInclude = std::regex_match(line, m, macroIncludeRe);
            if (macroInclude && fileDefine(m[1].str()) == nullptr) {
                // An include of a define the host did not set sits in that define's #ifdef, which
                // the GLSL preprocessor drops: nothing to include.
                out << "\n";
                continue;
            }
            if (macroInclude || std::regex_match(line, m, includeRe)) {
                const std::string* quoted = macroInclude ? fileDefine(m[1].str()) : nullptr;
                const fs::path target = quoted ? resolveFileDefine(*quoted, file, lineNo) : resolve(m[1].str(), file, lineNo);
                for (const auto& open : stack)
                    if (open == target)
                        throw ShaderError(file.string() + ":" + std::to_string(lineNo) +
                                          ": error: include cycle through " + target.string());
                if (included.insert(target).second) emit(target, nullptr);
                out << "#line " << lineNo + 1 << " " << index << "\n";
                continue;
            }
            out << line << "\n";
        }
        if (!versionSeen)
            throw ShaderError(file.string() + ":1: error: entry point has no #version line");
        stack.pop_back();
    }
};

} // namespace

ShaderSource assembleShader(const fs::path& entryFile, const ShaderDefines& defines,
                            const std::vector<fs::path>& includeDirs) {
    Assembler a;
    a.hostDefines = defines;
    a.includeDirs = includeDirs;
    const fs::path entry = fs::weakly_canonical(entryFile);
    a.included.insert(entry);
    a.emit(entry, &defines);
    return ShaderSource{a.out.str(), a.files};
}

std::string mapShaderLog(const std::string& log, const std::vector<fs::path>& files) {
    // Mesa: "0:12(5): error: ..."; NVIDIA: "0(12) : error ...".
    static const std::regex mesaRe(R"((\d+):(\d+)\((\d+)\))");
    static const std::regex nvRe(R"((\d+)\((\d+)\))");
    auto name = [&](const std::string& idx) {
        const size_t i = std::stoul(idx);
        return i < files.size() ? files[i].string() : "<source " + idx + ">";
    };
    std::ostringstream out;
    std::istringstream in(log);
    std::string line;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_search(line, m, mesaRe) && m.position(0) == 0)
            line = name(m[1]) + ":" + m[2].str() + ":" + m[3].str() + m.suffix().str();
        else if (std::regex_search(line, m, nvRe) && m.position(0) == 0)
            line = name(m[1]) + ":" + m[2].str() + m.suffix().str();
        out << line << "\n";
    }
    return out.str();
}

fs::path shaderDirectory() {
    return resourceDirectory(std::getenv("RAYLAB_SHADER_DIR"), "shaders", "entry", RAYLAB_SOURCE_SHADER_DIR);
}

} // namespace raylab
