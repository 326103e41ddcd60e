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

struct ParseResult {
    Json doc;
    bool ok = false;
    std::size_t errorOffset = 0;
    std::string reason;                 // the parser's explanation
    std::optional<JsonPath> errorPath;  // set for out-of-range numbers (known value position)
};

ParseResult parseJson(std::string_view text);

} // namespace raylab::scenefmt
