#pragma once
// The viewer's automation script (raylab --script FILE): one command per line, '#' starts a
// comment. Used by the tests under Xvfb and for reproducible screenshots. Commands:
//   open PATH              load a scene (errors are shown, the previous scene stays)
//   set KEY VALUE          edit a scene key (camera.fov 50, materials.red.albedo [1,0,0]);
//                          selected.KEY: a key of the selected object or of its material
//   click X Y              a left click at window pixel (X, Y), as the mouse would
//   pick X Y               select the object at image pixel (X, Y) of the traced image
//   select N               select object N (as the outliner does)
//   debug-view NAME        beauty, normals, albedo, depth, material-id, nan, noise, bounce,
//                          direct, indirect
//   debug-bounce K         the k of the "bounce" view (0 = what the camera ray hits)
//   overlay boxes on|off   object bounding boxes;  overlay selected on|off: only the selected one
//   scale S                resolution scale of the traced image (0.125 to 2)
//   pause | resume | reset
//   wait-spp N             wait until the image has N samples per pixel (or the target is reached)
//   wait-frames N          let N UI frames pass
//   screenshot PATH        the window as PNG;  export PATH: the render as EXR (linear) or PNG
//   save PATH              the scene as JSON
//   window W H             resize the window
//   quit                   exit with status 0 (non-zero if any command failed)
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace raylab::ui {

struct ScriptCommand {
    int line = 0;
    std::string name;
    std::vector<std::string> args;
    std::string text() const;   // "line N: name args..."
};

class ScriptError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Parses and checks every line up front (command names, argument counts and numbers), so a typo
// fails before the viewer opens. Errors read "FILE:LINE: error: what". `set` takes the rest of
// the line as its value (spaces allowed: [1, 0, 0]).
std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& fileName);
std::vector<ScriptCommand> loadScript(const std::filesystem::path& file);

} // namespace raylab::ui
