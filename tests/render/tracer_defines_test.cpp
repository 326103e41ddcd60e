// The one list of defines the host sets on the tracer (render/tracer_defines.h) against the
// entry points' header comments and against the host code that sets them.
#include "render/shader_variant.h"
#include "render/tracer_defines.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

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

TEST(TracerDefines, EveryEntryPointNamesEveryDefineItReceives) {
    const std::string frag = headerComment(kRoot / "shaders/entry/trace.frag");
    const std::string comp = headerComment(kRoot / "shaders/entry/trace.comp");
    for (const TracerDefine& d : kTracerDefines) {
        EXPECT_TRUE(namesWord(comp, d.name)) << "trace.comp's header does not name " << d.name;
        if (!d.computeOnly) {
            EXPECT_TRUE(namesWord(frag, d.name)) << "trace.frag's header does not name " << d.name;
        }
    }
    // fullscreen.vert is compiled with trace.frag's defines; it must say so and use none of them.
    const std::string vert = readFile(kRoot / "shaders/entry/fullscreen.vert");
    EXPECT_NE(headerComment(kRoot / "shaders/entry/fullscreen.vert").find("trace.frag"), std::string::npos);
    for (const TracerDefine& d : kTracerDefines) EXPECT_FALSE(namesWord(vert, d.name)) << d.name;
    // Every entry point states what its host sets, "none" included.
    for (const auto& e : fs::directory_iterator(kRoot / "shaders/entry"))
        EXPECT_NE(headerComment(e.path()).find("Defines set by the host"), std::string::npos) << e.path();
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
    }
    for (const TracerDefine& d : kTracerDefines)
        if (d.setBy == "render/shader_variant.cpp") {
            EXPECT_TRUE(set.count(std::string(d.name))) << d.name;
        }
}

TEST(TracerDefines, HostCodeNamesDefinesOnlyThroughTheList) {
    // A define written as a bare string in src/ or ui/ would bypass tracerDefine()'s compile-time
    // check. Environment variables (getenv) are not defines.
    const std::regex literal("\"((RAYLAB|LOCAL_SIZE)_[A-Z0-9_]+)\"");
    int checked = 0;
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
                ++checked;
                EXPECT_TRUE(before.ends_with("tracerDefine(")) << e.path() << ": " << (*it)[1] << " not through tracerDefine()";
                EXPECT_TRUE(listed((*it)[1])) << (*it)[1];
            }
        }
    EXPECT_GT(checked, 20);
}
