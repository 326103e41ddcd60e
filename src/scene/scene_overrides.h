#pragma once
// The renderer's --set KEY=VALUE: written into the parsed document before validation, so an
// override is checked exactly like the file's own value and its errors point at the --set.
#include "scene/json_path.h"

#include <string>

namespace raylab::scenefmt {

struct AppliedOverride {
    std::string pointer;  // of the value it wrote
    std::string text;     // as given, for messages
};

// Writes one "dotted.key=value" into `root`, creating missing objects along the path. The value is
// parsed as JSON when it parses, otherwise taken as a string. Throws SceneError for a malformed
// override or a path that cannot exist (an index past an array's end).
AppliedOverride applyOverride(Json& root, const std::string& text);

} // namespace raylab::scenefmt
