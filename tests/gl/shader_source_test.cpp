// Shader assembly (#include, defines, #line) and compile errors reported as file:line.
#include "gl/shader_program.h"
#include "render/shader_variant.h"
#include "support/gl_test.h"

#include <gtest/gtest.h>

#include <fstream>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

fs::path scratchDir(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / ("raylab_shader_test_" + name + std::to_string(::getpid()));
    fs::create_directories(dir / "inc");
    return dir;
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p) << text; }

} // namespace

TEST(ShaderSource, IncludesOnceDefinesAfterVersionAndNumericLines) {
    const fs::path dir = scratchDir("assemble");
    write(dir / "inc" / "a.glsl", "float a() { return 1.0; }\n");
    write(dir / "inc" / "b.glsl", "#include \"a.glsl\"\nfloat b() { return a(); }\n");
    write(dir / "main.comp", "#version 450 core\n#include \"inc/a.glsl\"\n#include \"inc/b.glsl\"\nvoid main() {}\n");
    const ShaderSource s = assembleShader(dir / "main.comp", {{"FOO", "3"}});
    EXPECT_EQ(s.text.rfind("#version 450 core\n#define FOO 3\n#line 2 0\n", 0), 0u) << s.text;
    EXPECT_EQ(s.files.size(), 3u);
    // a.glsl's body appears once even though it is included twice.
    const auto first = s.text.find("float a()");
    EXPECT_NE(first, std::string::npos);
    EXPECT_EQ(s.text.find("float a()", first + 1), std::string::npos);
    EXPECT_EQ(s.text.find("#line 1 \"", 0), std::string::npos) << "GLSL rejects file names in #line";
    fs::remove_all(dir);
}

TEST(ShaderSource, AFileDefineIsOneToGlslAndIncludesItsFileAtItsOwnLines) {
    const fs::path dir = scratchDir("filedefine");
    write(dir / "pupil.glsl", "float f() { return 2.0; }\n");
    write(dir / "main.comp", "#version 450 core\n#ifdef SLOT\n#include SLOT\n#else\nfloat f() { return 1.0; }\n#endif\n"
                             "#ifdef OTHER\n#include OTHER\n#endif\nvoid main() {}\n");
    const ShaderSource s = assembleShader(dir / "main.comp", {{"SLOT", "\"" + (dir / "pupil.glsl").string() + "\""}});
    EXPECT_NE(s.text.find("#define SLOT 1\n"), std::string::npos) << s.text;
    EXPECT_NE(s.text.find("#line 1 1\nfloat f() { return 2.0; }"), std::string::npos) << s.text;
    ASSERT_EQ(s.files.size(), 2u);
    EXPECT_EQ(s.files[1], fs::weakly_canonical(dir / "pupil.glsl"));
    // An include of a define the host did not set includes nothing (its #ifdef drops the line).
    EXPECT_EQ(assembleShader(dir / "main.comp").files.size(), 1u);
    try {
        assembleShader(dir / "main.comp", {{"SLOT", "\"" + (dir / "missing.glsl").string() + "\""}});
        ADD_FAILURE() << "a missing pupil file was accepted";
    } catch (const ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("main.comp:3: error: cannot find included file"), std::string::npos) << e.what();
    }
    fs::remove_all(dir);
}

TEST(ShaderSource, TheCplusplusHalfOfASharedHeaderArrivesBlankAtItsOwnLines) {
    // Mesa looks a source up in its shader cache before preprocessing it only when the text holds
    // no "#include": the C++ half's <glm/glm.hpp> must not reach it.
    const fs::path dir = scratchDir("cplusplus");
    write(dir / "shared.glsl", "#ifdef __cplusplus\n#include <glm/glm.hpp>\n#if 1\nint cpp;\n#endif\n#define X 2\n"
                               "#else\n#define X 1\n#endif\nfloat shared() { return X; }\n");
    write(dir / "main.comp", "#version 450 core\n#include \"shared.glsl\"\nvoid main() {}\n");
    const ShaderSource s = assembleShader(dir / "main.comp");
    EXPECT_EQ(s.text.find("#include"), std::string::npos) << s.text;
    EXPECT_EQ(s.text.find("cpp"), std::string::npos) << s.text;
    EXPECT_NE(s.text.find("#line 1 1\n#ifdef __cplusplus\n\n\n\n\n\n#else\n#define X 1\n#endif\nfloat shared()"),
              std::string::npos) << s.text;
    fs::remove_all(dir);
}

TEST(ShaderSource, TheShippedTracerReachesTheCompilerWithoutAnInclude) {
    const fs::path dir = shaderDirectory();
    for (const char* entry : {"entry/trace.frag", "entry/trace.comp", "entry/display.frag"}) {
        const ShaderSource s = assembleShader(dir / entry, featureDefines(allFeatures()), {dir / "include"});
        EXPECT_EQ(s.text.find("#include"), std::string::npos) << entry;
    }
}

TEST(ShaderSource, MissingIncludeAndCycleAreLocated) {
    const fs::path dir = scratchDir("missing");
    write(dir / "main.comp", "#version 450 core\n\n#include \"nope.glsl\"\n");
    try {
        assembleShader(dir / "main.comp");
        FAIL() << "expected ShaderError";
    } catch (const ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("main.comp:3: error: cannot find included file \"nope.glsl\""),
                  std::string::npos) << e.what();
    }
    write(dir / "x.glsl", "#include \"y.glsl\"\n");
    write(dir / "y.glsl", "#include \"x.glsl\"\n");
    write(dir / "cycle.comp", "#version 450 core\n#include \"x.glsl\"\n");
    EXPECT_THROW(assembleShader(dir / "cycle.comp"), ShaderError);
    fs::remove_all(dir);
}

TEST(ShaderSource, MapsMesaAndNvidiaLocations) {
    const std::vector<fs::path> files = {"entry.comp", "inc/util.glsl"};
    EXPECT_EQ(mapShaderLog("1:12(5): error: `x' undeclared\n", files), "inc/util.glsl:12:5: error: `x' undeclared\n");
    EXPECT_EQ(mapShaderLog("0(7) : error C1008: bad\n", files), "entry.comp:7 : error C1008: bad\n");
}

class ShaderCompileTest : public test::GlTest {};

TEST_F(ShaderCompileTest, CompileErrorNamesTheIncludedFileAndLine) {
    const fs::path dir = scratchDir("compile");
    write(dir / "inc" / "broken.glsl", "// line 1\nfloat ok() { return 1.0; }\nfloat bad() { return undefinedThing; }\n");
    write(dir / "main.comp",
          "#version 450 core\nlayout(local_size_x = 1) in;\n#include \"inc/broken.glsl\"\nvoid main() { ok(); }\n");
    try {
        ShaderProgram::computeFromFile(dir / "main.comp");
        FAIL() << "expected ShaderError";
    } catch (const ShaderError& e) {
        const std::string msg = e.what();
        EXPECT_NE(msg.find("broken.glsl:3:"), std::string::npos) << msg;
        EXPECT_NE(msg.find("undefinedThing"), std::string::npos) << msg;
    }
    // An error in the entry file itself, after the include, keeps the entry's own numbering.
    write(dir / "main2.comp",
          "#version 450 core\nlayout(local_size_x = 1) in;\n#include \"inc/broken.glsl\"\nvoid main() { nothere(); }\n");
    write(dir / "inc" / "broken.glsl", "float ok() { return 1.0; }\n");
    try {
        ShaderProgram::computeFromFile(dir / "main2.comp");
        FAIL() << "expected ShaderError";
    } catch (const ShaderError& e) {
        EXPECT_NE(std::string(e.what()).find("main2.comp:4:"), std::string::npos) << e.what();
    }
    fs::remove_all(dir);
}

TEST_F(ShaderCompileTest, ShippedEntryPointsCompile) {
    const ShaderDefines features = featureDefines(allFeatures());
    ShaderDefines compute = features;
    compute.insert(compute.end(), {{"LOCAL_SIZE_X", "8"}, {"LOCAL_SIZE_Y", "8"}});
    EXPECT_NO_THROW(ShaderProgram::graphics("entry/fullscreen.vert", "entry/trace.frag", features));
    EXPECT_NO_THROW(ShaderProgram::compute("entry/trace.comp", compute));
}
