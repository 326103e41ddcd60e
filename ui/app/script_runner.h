#pragma once
// Runs an automation script (app/script.h) one step per UI frame against the viewer, so each
// command sees the frames before it drawn: waits (wait-spp, wait-frames, a pending screenshot)
// hold the script, everything else runs at once. Window operations go through ScriptHost.
#include "script/script.h"
#include "app/ui_state.h"
#include "app/viewer.h"

#include <cstddef>
#include <vector>

namespace raylab::ui {

class ScriptHost {
public:
    virtual ~ScriptHost() = default;
    virtual void resizeWindow(int width, int height) = 0;
};

class ScriptRunner {
public:
    ScriptRunner(std::vector<ScriptCommand> commands, double timeoutSeconds);
    // Call once per frame before the views are drawn. Returns false once the script has ended
    // (quit, end of file or timeout); exitCode() then says how.
    bool step(Viewer& viewer, UiState& ui, ScriptHost& host, double now);
    int exitCode() const { return exitCode_; }
    int failures() const { return failures_; }

private:
    bool run(const ScriptCommand& c, Viewer& viewer, UiState& ui, ScriptHost& host);   // false = failed
    std::vector<ScriptCommand> commands_;
    std::size_t next_ = 0;
    double timeout_;
    double start_ = -1.0;
    int waitFrames_ = 0;
    long long waitSpp_ = -1;
    int failures_ = 0;
    int exitCode_ = 0;
    bool finished_ = false;
};

} // namespace raylab::ui
