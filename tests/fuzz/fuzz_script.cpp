// libFuzzer harness of the script language: the input is parsed as a script (parseScript, what
// `raylab --script` runs) and as a lesson (parseLesson, whose ```raylab blocks are scripts; its
// root is the scratch folder, which holds scene.json). Only ScriptError and LessonError are expected.
#include "fuzz_support.h"

#include "lesson/lesson.h"
#include "script/script.h"

#include <exception>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace raylab;
    const std::string text(reinterpret_cast<const char*>(data), size);
    try {
        parseScript(text, "fuzz.script");
    } catch (const ScriptError&) {
    } catch (const std::exception& e) {
        fuzz::unexpected("fuzz_script: parseScript", e.what());
    }
    const std::filesystem::path& root = fuzz::scratchDir();
    try {
        parseLesson(text, root / "lessons" / "fuzz.md", root);
    } catch (const LessonError&) {
    } catch (const std::exception& e) {
        fuzz::unexpected("fuzz_script: parseLesson", e.what());
    }
    return 0;
}
