#pragma once
// JSON text (with // and /* */ comments) -> document, with the byte offset of a syntax error.
// nlohmann reports number overflow (1e999) as an exception without position; its SAX interface gives
// the position, so the document is built through our own SAX handler.
#include "scene/json_path.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace raylab::scenefmt {

// Arrays and objects nested deeper than this are an error: a scene needs six levels, and the limit
// keeps every later recursive walk (the locator, the document's destructor, printing) shallow.
inline constexpr std::size_t kMaxJsonDepth = 64;

struct ParseResult {
    Json doc;
    bool ok = false;
    std::size_t errorOffset = 0;
    std::string reason;                 // the parser's explanation
    std::optional<JsonPath> errorPath;  // set where the value's place is known (too large, too deep)
};

// The whole text must be one document: anything but whitespace and comments after it, a NUL byte
// included, is an error at its offset.
ParseResult parseJson(std::string_view text);

} // namespace raylab::scenefmt
