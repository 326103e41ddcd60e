#pragma once
// The viewer's command line: `raylab [SCENE] [--script FILE] ...` (raylab --help).
#include "app/script_runner.h"

#include <optional>
#include <string>
#include <vector>

namespace raylab::ui {

struct AppOptions {
    std::string scenePath;             // the lesson's or the default scene when not given
    std::string iniPath = "imgui.ini";
    std::vector<int> windowSize{1280, 800};
    float scale = 1.0f;
    std::vector<std::string> sets;     // KEY=VALUE
    double targetFrameMs = 30.0;
    int maxFrames = 0;
    int skipFrames = 30;
    double scriptTimeout = 300.0;
    bool reportFrames = false;
    std::string frameLog;              // per-frame time and resident memory, written at exit
    bool vsync = false;
    bool continuous = false;
    std::string lessonPath;            // --lesson, already the --lang edition's file
    std::string language;              // --lang: the lessons' edition ("" = English, or the lesson's own)
    std::string exercise;              // --exercise: a code-track exercise whose pupil file the tracer runs
    std::string exerciseDir;           // --exercise-dir: where the pupil's files are (default: the stubs')
    bool classMode = false;            // --class: the teacher's notes only on the presenter view
    bool presenterWindow = false;      // --presenter-window: the presenter view in a window of its own, shown at start
    float uiScale = 0.0f;              // 0: as the layout file says
    std::optional<ScriptRunner> script;
};

// Parses argv, loads the script and checks the lesson before a window opens. nullopt: go on;
// otherwise the exit status (--help, or a located error already printed).
std::optional<int> parseCommandLine(int argc, char** argv, AppOptions& options);

} // namespace raylab::ui
