#include "app_cli.h"

#include "app/ui_state.h"
#include "exercise/manifest.h"
#include "gl/shader_source.h"
#include "lesson/lesson.h"
#include "lesson/lesson_edition.h"
#include "lesson/lesson_words.h"
#include "script/script.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>

namespace raylab::ui {
namespace {

namespace fs = std::filesystem;

fs::path defaultScene() {
    const fs::path candidate = shaderDirectory() / ".." / "scenes" / "default.json";
    std::error_code ec;
    return fs::exists(candidate, ec) ? fs::weakly_canonical(candidate, ec) : fs::path();
}

} // namespace

std::optional<int> parseCommandLine(int argc, char** argv, AppOptions& o) {
    CLI::App app{"raylab: the interactive path tracer (GLFW + ImGui viewer)"};
    std::string scriptPath;
    app.add_option("scene", o.scenePath, "Scene file (default: scenes/default.json)");
    app.add_option("--script", scriptPath, "Automation script: one command a line (see src/script/script.h)");
    app.add_option("--script-timeout", o.scriptTimeout, "Seconds before a script that has not quit fails")->capture_default_str();
    app.add_option("--window", o.windowSize, "Window size W H")->expected(2)->capture_default_str();
    app.add_option("--scale", o.scale, "Resolution scale of the traced image")->check(CLI::Range(0.125, 2.0))->capture_default_str();
    app.add_option("--set", o.sets, "KEY=VALUE scene override after loading (repeatable)");
    app.add_option("--ini", o.iniPath, "Layout file ('' = do not save the layout)")->capture_default_str();
    app.add_option("--frame-time", o.targetFrameMs, "Target milliseconds per UI frame; tracing gets what the UI leaves")
        ->check(CLI::Range(1.0, 1000.0))->capture_default_str();
    app.add_option("--frames", o.maxFrames, "Quit after this many frames (benchmarks)");
    app.add_option("--skip-frames", o.skipFrames, "Frames left out of --report-frames (warm-up)")->capture_default_str();
    app.add_flag("--report-frames", o.reportFrames, "Print frame-time statistics at exit");
    app.add_option("--frame-log", o.frameLog,
                   "Write each frame's time (ms) and the resident memory (MiB) after it to FILE at exit, one frame a line "
                   "(soak tests)")->type_name("FILE");
    app.add_flag("--vsync", o.vsync, "Wait for the display's refresh");
    app.add_flag("--continuous", o.continuous,
                 "Redraw the UI every frame even when idle (by default, with no input the UI redraws when a "
                 "pass completes or every 0.25 s, and tracing gets the time in between)");
    app.add_option("--exercise", o.exercise, "Run the tracer with a pupil's function for this exercise (raylab-exercise list)");
    app.add_option("--exercise-dir", o.exerciseDir, "Folder of the pupil's exercise files (default: the shipped stubs)");
    app.add_flag("--class", o.classMode, "Class mode: answers and teacher's notes only on the presenter view (F2)");
    app.add_flag("--presenter-window", o.presenterWindow,
                 "The presenter view (lesson position, clock, notes and answers) in a second window, for the teacher's screen");
    app.add_option("--lesson", o.lessonPath, "Open a lesson (lessons/NN-topic.md) in the Teach window; its scene unless SCENE is given");
    app.add_option("--lang", o.language,
                   "The lessons' language: en, or nl for the Dutch edition (lessons/nl/): the Teach window's lessons and --lesson's")
        ->type_name("LANG");
    app.add_option("--ui-scale", o.uiScale, "UI scale for projectors (default: as last time, from the layout file)")
        ->check(CLI::Range(double(kMinUiScale), double(kMaxUiScale)));
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    if (!o.exercise.empty()) {
        try {   // fail before a window opens
            const auto exercises = loadManifest();
            const Exercise* e = findExercise(exercises, o.exercise);
            if (!e) throw std::runtime_error("--exercise: no exercise \"" + o.exercise + "\" (raylab-exercise list)");
            const std::filesystem::path file =
                (o.exerciseDir.empty() ? exerciseDirectory() : std::filesystem::path(o.exerciseDir)) / e->file;
            if (!std::filesystem::is_regular_file(file))
                throw std::runtime_error(file.string() + ": error: no such pupil file (--exercise-dir)");
        } catch (const std::exception& e) {
            std::fprintf(stderr, "raylab: %s\n", e.what());
            return 1;
        }
    }
    if (!o.language.empty() && !isLessonLanguage(o.language)) {
        std::fprintf(stderr, "raylab: --lang: unknown language '%s' (%s)\n", o.language.c_str(), lessonLanguageList().c_str());
        return 1;
    }
    if (!o.lessonPath.empty()) {
        try {
            if (!o.language.empty()) {
                const auto edition = lessonInLanguage(o.lessonPath, o.language);
                if (!edition)
                    throw std::runtime_error(o.lessonPath + ": error: --lang needs a lesson in lessons/ or lessons/LANG/");
                o.lessonPath = edition->string();
            }
            const Lesson lesson = loadLesson(o.lessonPath);   // fail before a window opens
            if (o.scenePath.empty()) o.scenePath = lesson.scenePath.string();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "raylab: %s\n", e.what());
            return 1;
        }
    }
    if (!scriptPath.empty()) {
        try {
            o.script.emplace(loadScript(scriptPath), o.scriptTimeout);
        } catch (const std::exception& e) {
            std::fprintf(stderr, "raylab: %s\n", e.what());
            return 1;
        }
    }
    if (o.scenePath.empty()) o.scenePath = defaultScene().string();
    return std::nullopt;
}

} // namespace raylab::ui
