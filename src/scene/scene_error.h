#pragma once
// How the scene format's errors are worded and where they point: the validator throws a
// ValidationFailure at a document path, and placeFailure turns it into "FILE:LINE:COL: error: PATH:
// what" or, when a --set override wrote the value, "--set KEY=VALUE: error: PATH: what".
#include "scene/json_locator.h"
#include "scene/json_parse.h"
#include "scene/json_path.h"

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

// Error with a message already formatted as "FILE:LINE:COL: error: PATH: what" (or, for --set
// overrides, "--set KEY=VALUE: error: PATH: what"). PATH is like objects[2].radius.
class SceneError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

namespace scenefmt {

struct AppliedOverride;

// The first validation problem: thrown inside the validator, turned into a SceneError with a location.
struct ValidationFailure {
    JsonPath path;
    std::string message;
    bool atKey = false;  // point at the member's key rather than its value (unknown/duplicate keys)
};

[[noreturn]] void fail(const JsonPath& path, std::string message, bool atKey = false);

// Fails at key `key` of the object at `path`: unknown there, with the closest of `known` suggested.
[[noreturn]] void failUnknownKey(const JsonPath& path, std::string_view key, const std::vector<std::string_view>& known);

// Pieces of messages.
std::string inQuotes(std::string_view s);                      // 'radius', long names cut short
std::string joinNames(const std::vector<std::string_view>& names);   // a, b, c
std::string inWhere(const JsonPath& p);                        // "in render", "at the top level"
// "; did you mean 'radius'?" when a candidate is close, else the full list.
std::string suggestion(std::string_view word, const std::vector<std::string_view>& candidates,
                       std::string_view listName);

std::string fileLocation(const std::string& fileName, SourcePos pos);   // "FILE:LINE:COL: error: "

// What is wrong with a parsed document before any key is read, located in `fileName`: its syntax
// error, or its first repeated key; empty when neither.
std::string documentError(const ParseResult& parsed, const JsonLocator& locator, const std::string& fileName);
std::string overridePrefix(const std::string& text);                    // "--set KEY=VALUE: error: "

// Formats a validation failure: at the override that wrote (or created) the value, else at the
// value (or key) in the file, else at the nearest enclosing value that is in the file.
std::string placeFailure(const ValidationFailure& f, const std::string& fileName, const JsonLocator& locator,
                         const std::vector<AppliedOverride>& overrides);

} // namespace scenefmt
} // namespace raylab
