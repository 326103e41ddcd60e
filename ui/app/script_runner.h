#pragma once
// Runs an automation script (script/script.h) one step per UI frame against the viewer, so each
// command sees the frames before it drawn: waits (wait-spp, wait-frames, a pending screenshot)
// hold the script, everything else runs at once. Window operations go through ScriptHost.
#include "script/script.h"
#include "app/ui_state.h"
#include "app/viewer.h"

#include <cstddef>
#include <string>
#include <vector>

namespace raylab::ui {

class ScriptHost {
public:
    virtual ~ScriptHost() = default;
    virtual void resizeWindow(int width, int height) = 0;
    // As if the file had been dropped on the window (the window's drop callback).
    virtual void dropFile(const std::string& path) = 0;
};

class ScriptRunner {
public:
    ScriptRunner(std::vector<ScriptCommand> commands, double timeoutSeconds);
    // Call once per frame before the views are drawn. Returns false once the script has ended
    // (quit, end of file or timeout); exitCode() then says how.
    bool step(Viewer& viewer, UiState& ui, ScriptHost& host, double now);
    int exitCode() const { return exitCode_; }
    // Tests: wait-spp N waits for at most this many samples (lesson steps ask for up to 1024).
    void limitWaits(long long maxSpp) { maxWaitSpp_ = maxSpp; }
    // This runner runs a lesson step's script: it does not wait for lesson steps (as an automation
    // script does, so its next command sees the step's state).
    void markLessonStep() { lessonStep_ = true; }
    int failures() const { return failures_; }

private:
    bool run(const ScriptCommand& c, Viewer& viewer, UiState& ui, ScriptHost& host);   // false = failed
    std::vector<ScriptCommand> commands_;
    std::size_t next_ = 0;
    double timeout_;
    double start_ = -1.0;
    int waitFrames_ = 0;
    long long waitSpp_ = -1;
    long long maxWaitSpp_ = (1LL << 62);
    bool lessonStep_ = false;
    int failures_ = 0;
    int exitCode_ = 0;
    bool finished_ = false;
};

} // namespace raylab::ui
