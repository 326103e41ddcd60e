#pragma once
// A value's place in a scene document, shown to people as objects[2].radius and to JsonLocator as
// the JSON pointer /objects/2/radius.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace raylab::scenefmt {

// Parsed documents keep the file's key order, so that validation meets problems in reading order.
using Json = nlohmann::ordered_json;

struct JsonPath {
    struct Segment {
        std::string token;
        bool index = false;
    };
    std::vector<Segment> segments;

    JsonPath key(std::string_view k) const;
    JsonPath index(std::size_t i) const;
    std::string pointer() const;   // "/objects/2/radius", RFC 6901 escaping
    std::string display() const;   // "objects[2].radius", materials["my lamp"], "(top level)"
};

// Rebuilds a path (with array/key distinction) from a JSON pointer by walking the document.
JsonPath pathFromPointer(const Json& doc, std::string_view pointer);

// True when `pointer` is `prefix` or lies inside it.
bool isPointerPrefix(std::string_view prefix, std::string_view pointer);

// A name from a document as messages show it: past 40 bytes, cut with "...".
std::string shortText(std::string_view text);

// "number", "string", "empty string", "array", ...: the JSON type of a value, for messages.
std::string typeOf(const Json& v);

} // namespace raylab::scenefmt
