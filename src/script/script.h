#pragma once
// raylab's automation script: one command per line, '#' starts a comment. The viewer runs it
// (raylab --script FILE, tests under Xvfb, reproducible screenshots) and lessons use it for the
// state each step sets (lessons/README.md). Commands:
//   open PATH              load a scene (errors are shown, the previous scene stays)
//   drop PATH              drop a file on the window: the window's drop handling opens it next
//                          frame (a failed open shows its error; the script goes on)
//   set KEY VALUE          edit a scene key (camera.fov 50, materials.red.albedo [1,0,0]);
//                          selected.KEY: a key of the selected object or of its material, or
//                          of the selected light (selected.intensity)
//   click X Y              a left click at window pixel (X, Y), as the mouse would
//   pick X Y               select the object at image pixel (X, Y) of the traced image
//   select N               select object N (as the outliner does: spheres, then meshes; -1 none)
//   select-light N         select light N of the scene's `lights` (the outliner's light rows; -1 none)
//   focus X Y              click-to-focus at image pixel (X, Y): camera.focus_distance becomes the
//                          distance of the surface there along the view axis
//   focus-mode on|off      the Camera panel's "click to focus": the next click focuses, not picks
//   debug-view NAME        a view of shaders/include/debug_view_table.glsl (beauty, normals, ...);
//                          debug-bounce K: the bounce the "bounce" view shows;
//                          heat-scale auto|N: the count shown red
//   overlay boxes on|off   object bounding boxes;  overlay selected on|off: only the selected one;
//                          overlay paths on|off: the inspected pixel's paths;
//                          overlay lights on|off: a gizmo per light
//   overlay bvh on|off     top-level BVH nodes at the chosen depth; overlay mesh-bvh on|off: the
//                          meshes' BVH nodes at that depth;  bvh-depth N: the depth (0 = root)
//   inspect X Y [N]        record the next N (default: the Inspector's count, 8) sample paths of
//                          pixel (X, Y) of the scene's image (render.width × height, mapped
//                          through the resolution scale) with every estimator term
//   inspect-export PATH    the inspected paths as .json or .csv
//   explore K [P]          BRDF explorer at bounce K of inspected path P (default 0): its material
//                          and incoming direction
//   panel inspector|brdf-explorer on|off   show or hide that panel
//   scale S                resolution scale of the traced image (0.125 to 2)
//   pause | resume | reset
//   wait-spp N             wait until the image has N samples per pixel (or the target is reached)
//   expect KEY VALUE       fails unless the scene's KEY has VALUE now (script/expectation.h):
//                          the state a lesson step's text describes; also expect debug-view NAME,
//                          expect scale S and expect bounce-step K|off for the viewer's state
//   wait-frames N          let N UI frames pass
//   screenshot PATH        the window as PNG;  export PATH: the render as EXR (linear) or PNG
//   save PATH              the scene as JSON
//   window W H             resize the window
//   quit                   exit with status 0 (non-zero if any command failed)
// Teaching and classroom (the viewer's Teach window; lessons use the first five):
//   hold                   a lesson step's sub-steps meet here: the presenter's key runs what
//                          follows (lesson/lesson.h); a script that is not a lesson step fails on it
//   bounce-step K|next|off trace with at most K bounces (bounce views 0..K); next: K + 1; off
//   stage NAME             = set render.stage NAME (primary, emission, lambert, ggx, textures, full)
//   split samples|time|off A/B split screen at equal samples or equal time; off clears it
//   split-a KEY VALUE      an override of side A (left); split-b KEY VALUE: of side B (right);
//                          KEY debug-view: the side traces that view (split-a debug-view ao)
//   split-divider X        where the sides meet, 0 to 1 of the image width
//   ui-scale S             UI scale for projectors (0.5 to 4)
//   key NAME [FRAMES]      press a key in the window, through the window's own key handling, and
//                          hold it FRAMES frames (default 1): a name of script/key_actions.h
//                          (page-down, page-up, space, r, f5, f9, f12, f1, f2, ctrl+s, ctrl+=, ctrl+-,
//                          ctrl+0), or a camera key, which gives the viewport the keyboard and
//                          acts while held (w, s forward/back, a, d left/right, q, e down/up;
//                          left, right turn, up, down look up/down)
//   lesson PATH            open a lesson in the Lesson panel;  lesson-step N: apply its step N
//   self-test              run the self-test (furnace, χ² of the GLSL samplers), log the verdicts
//   teach TAB              show the Teach window at lesson, classroom or self-test; off hides it
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

struct ScriptCommand {
    int line = 0;   // 1-based line in the file the command came from
    std::string name;
    std::vector<std::string> args;
    std::string text() const;   // "line N: name args..."
};

class ScriptError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// The names `debug-view` accepts, in the order the viewer lists them.
std::span<const std::string_view> scriptDebugViews();
// The names `key` accepts (script/key_actions.h).
std::span<const std::string_view> scriptKeys();

// Parses and checks every line up front (command names, argument counts and numbers), so a typo
// fails before the viewer opens. Errors read "FILE:LINE: error: what"; LINE is firstLine plus the
// line's index in `text` (firstLine 1 for a whole file; a lesson passes the line after its fence).
// `set` takes the rest of the line as its value (spaces allowed: [1, 0, 0]).
std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& fileName, int firstLine = 1);
std::vector<ScriptCommand> loadScript(const std::filesystem::path& file);

} // namespace raylab
