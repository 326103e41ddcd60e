// The one list of defines the host sets on the tracer (render/tracer_defines.h) against the
// shaders that read them and the host code that sets them.
#include "render/shader_variant.h"
#include "render/tracer_defines.h"
#include "support/gl_test.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

const fs::path kRoot = RAYLAB_SOURCE_DIR;

std::string readFile(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The comment lines at the top of an entry point (after #version), up to the first other line.
std::string headerComment(const fs::path& p) {
    std::istringstream in(readFile(p));
    std::string line, header;
    while (std::getline(in, line)) {
        if (line.rfind("#version", 0) == 0) continue;
        if (line.rfind("//", 0) != 0) break;
        header += line + "\n";
    }
    return header;
}

bool namesWord(const std::string& text, std::string_view name) {
    return std::regex_search(text, std::regex("\\b" + std::string(name) + "\\b"));
}

bool listed(const std::string& name) {
    for (const TracerDefine& d : kTracerDefines)
        if (d.name == name) return true;
    return false;
}

} // namespace

// Every shader file and test entry point, for the scans below.
std::vector<fs::path> shaderFiles() {
    std::vector<fs::path> files;
    for (const auto& e : fs::recursive_directory_iterator(kRoot / "shaders")) files.push_back(e.path());
    for (const auto& e : fs::directory_iterator(kRoot / "tests/support"))
        if (e.path().extension() == ".comp") files.push_back(e.path());
    return files;
}

TEST(TracerDefines, EveryListedDefineIsReadByTheTracerAndTheVertexStageReadsNone) {
    std::string tracer;
    for (const fs::path& p : shaderFiles())
        if (p.filename() != "fullscreen.vert") tracer += readFile(p);
    for (const TracerDefine& d : kTracerDefines) EXPECT_TRUE(namesWord(tracer, d.name)) << d.name << " is read by no shader";
    // fullscreen.vert is compiled with trace.frag's defines; it must say so and use none of them.
    const std::string vert = readFile(kRoot / "shaders/entry/fullscreen.vert");
    EXPECT_NE(headerComment(kRoot / "shaders/entry/fullscreen.vert").find("trace.frag"), std::string::npos);
    for (const TracerDefine& d : kTracerDefines) EXPECT_FALSE(namesWord(vert, d.name)) << d.name;
    // Every entry point states what its host sets, "none" included.
    for (const auto& e : fs::directory_iterator(kRoot / "shaders/entry"))
        EXPECT_NE(headerComment(e.path()).find("Defines set by the host"), std::string::npos) << e.path();
}

TEST(TracerDefines, ShadersTestOnlyDefinesTheHostSetsOrTheyDefine) {
    // An undefined name in #if is 0 (ShaderPreprocessor.AnUndefinedNameInIfIsZero), so a misspelt
    // define would compile its code out silently: every RAYLAB_ name in an #if or #elif must be
    // one the host sets or one a shader #defines.
    std::set<std::string> known;
    for (const TracerDefine& d : kTracerDefines) known.insert(std::string(d.name));
    const std::regex define(R"(#\s*define\s+(RAYLAB_\w+))");
    const std::regex condition(R"(^\s*#\s*(if|elif)\b(.*))");
    const std::regex name(R"(\bRAYLAB_\w+)");
    for (const fs::path& p : shaderFiles()) {
        const std::string text = readFile(p);
        for (auto it = std::sregex_iterator(text.begin(), text.end(), define); it != std::sregex_iterator(); ++it)
            known.insert((*it)[1]);
    }
    int conditions = 0;
    for (const fs::path& p : shaderFiles()) {
        std::istringstream in(readFile(p));
        std::string line;
        for (int n = 1; std::getline(in, line); ++n) {
            std::smatch m;
            if (!std::regex_search(line, m, condition)) continue;
            const std::string expr = m[2];
            for (auto it = std::sregex_iterator(expr.begin(), expr.end(), name); it != std::sregex_iterator(); ++it) {
                ++conditions;
                EXPECT_TRUE(known.count(it->str())) << fs::relative(p, kRoot).string() << ":" << n << ": " << it->str()
                                                    << " is neither set by the host (tracer_defines.h) nor defined by a shader";
            }
        }
    }
    EXPECT_GT(conditions, 50);
}

class ShaderPreprocessor : public test::GlTest {
protected:
    // Compiles a compute shader of `body` after #version; false when it does not compile.
    static bool compiles(const std::string& body) {
        const fs::path file = fs::temp_directory_path() / "raylab_preprocessor_test.comp";
        std::ofstream(file) << "#version 450 core\n" << body << "\nlayout(local_size_x = 1) in;\nvoid main() {}\n";
        bool ok = true;
        try {
            ShaderProgram::computeFromFile(file);
        } catch (const ShaderError&) {
            ok = false;
        }
        fs::remove(file);
        return ok;
    }
};

TEST_F(ShaderPreprocessor, AnUndefinedNameInIfIsZero) {
    EXPECT_TRUE(compiles("#if RAYLAB_NOT_DEFINED_ANYWHERE\n#error taken\n#endif"));
    EXPECT_FALSE(compiles("#if !RAYLAB_NOT_DEFINED_ANYWHERE\n#error taken\n#endif")) << "the control: #error stops";
}

TEST_F(ShaderPreprocessor, TheTracerStopsWithoutTheSceneFeatures) {
    try {
        ShaderProgram::compute("entry/trace.comp", {{"LOCAL_SIZE_X", "8"}, {"LOCAL_SIZE_Y", "8"}});
        ADD_FAILURE() << "compiled without featureDefines()";
    } catch (const ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("features.glsl"), std::string::npos) << e.what();
    }
    ShaderDefines defines = featureDefines(allFeatures());
    defines.insert(defines.end(), {{"LOCAL_SIZE_X", "8"}, {"LOCAL_SIZE_Y", "8"}});
    EXPECT_NO_THROW(ShaderProgram::compute("entry/trace.comp", defines));
}

TEST(TracerDefines, TheSceneFeaturesSetOnlyListedDefinesAndEveryListedOne) {
    // Every feature on, the linear top level, the mip view and a teaching stage: the largest set.
    SceneFeatures f = allFeatures();
    f.linearTopLevel = true;
    f.showMipLevel = true;
    f.stage = RenderStage::Lambert;
    std::set<std::string> set;
    for (const auto& [name, value] : featureDefines(f)) {
        EXPECT_TRUE(listed(name)) << name << " is not in kTracerDefines";
        set.insert(name);
        if (name != "RAYLAB_STAGE") {
            EXPECT_TRUE(value == "0" || value == "1") << name << "=" << value;
        }
    }
    // A feature that is off is emitted as 0, not left out: the same names for any scene.
    std::set<std::string> none;
    SceneFeatures off;
#define RL_FEATURE_OFF(def, field, needs, name) off.field = false;
    RAYLAB_FEATURE_LIST(RL_FEATURE_OFF)
#undef RL_FEATURE_OFF
    for (const auto& [name, value] : featureDefines(off)) none.insert(name);
    EXPECT_EQ(none, set);
    for (const TracerDefine& d : kTracerDefines)
        if (d.setBy == "render/shader_variant.cpp") {
            EXPECT_TRUE(set.count(std::string(d.name))) << d.name;
        }
}

TEST(TracerDefines, HostCodeNamesDefinesOnlyThroughTheList) {
    // A define written as a bare string in src/ or ui/ would bypass tracerDefine()'s compile-time
    // check. Environment variables (getenv) are not defines.
    const std::regex literal("\"((RAYLAB|LOCAL_SIZE)_[A-Z0-9_]+)\"");
    std::set<std::string> found;
    for (const char* top : {"src", "ui"})
        for (const auto& e : fs::recursive_directory_iterator(kRoot / top)) {
            const std::string ext = e.path().extension().string();
            if (ext != ".cpp" && ext != ".h") continue;
            if (e.path().filename() == "tracer_defines.h") continue;
            const std::string text = readFile(e.path());
            for (auto it = std::sregex_iterator(text.begin(), text.end(), literal); it != std::sregex_iterator(); ++it) {
                const std::size_t at = std::size_t(it->position(0));
                const std::string before = text.substr(at >= 16 ? at - 16 : 0, at >= 16 ? 16 : at);
                if (before.ends_with("getenv(")) continue;
                found.insert((*it)[1]);
                EXPECT_TRUE(before.ends_with("tracerDefine(")) << e.path() << ": " << (*it)[1] << " not through tracerDefine()";
                EXPECT_TRUE(listed((*it)[1])) << (*it)[1];
            }
        }
    // The scan sees the defines host code names one by one (features come from the list).
    for (const char* name : {"RAYLAB_DEBUG_VIEWS", "RAYLAB_DEBUG_MOMENTS", "RAYLAB_COUNT_TRAVERSAL",
                             "RAYLAB_INSPECT_PATHS", "RAYLAB_STAGE", "LOCAL_SIZE_X", "LOCAL_SIZE_Y"})
        EXPECT_TRUE(found.count(name)) << "the scan did not find " << name;
}
