#include "scene/scene_overrides.h"

#include "scene/json_parse.h"
#include "scene/scene_error.h"
#include "scene/scene_keys.h"

#include <algorithm>
#include <cctype>
#include <utility>
#include <vector>

namespace raylab::scenefmt {
namespace {

bool looksLikeJson(std::string_view v) {
    const auto first = v.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return false;
    const char c = v[first];
    return c == '[' || c == '{' || c == '"' || c == '-' || std::isdigit(static_cast<unsigned char>(c));
}

} // namespace

AppliedOverride applyOverride(Json& root, const std::string& text) {
    auto error = [&text](const JsonPath* at, const std::string& what) -> SceneError {
        return SceneError(overridePrefix(text) + (at ? at->display() + ": " : std::string()) + what);
    };
    const auto eq = text.find('=');
    if (eq == std::string::npos) throw error(nullptr, "expected KEY=VALUE, e.g. render.spp=256");
    const std::string key = text.substr(0, eq);
    const std::string valueText = text.substr(eq + 1);

    std::vector<std::string> segments;
    try {
        segments = splitKey(key);
    } catch (const EditError& e) {
        throw error(nullptr, e.what());
    }
    if (segments.size() > kMaxJsonDepth)
        throw error(nullptr, "the key has " + std::to_string(segments.size()) + " parts; a scene nests at most " +
                                 std::to_string(kMaxJsonDepth) + " levels");

    Json value;
    ParseResult parsed = parseJson(valueText);
    if (parsed.ok) {
        value = std::move(parsed.doc);
    } else if (looksLikeJson(valueText)) {
        throw error(nullptr, "the value is not valid JSON: " + parsed.reason);
    } else {
        value = valueText;  // a bare word, e.g. sky.type=constant
    }

    if (!root.is_object()) throw error(nullptr, "the scene file's top level is not an object");
    Json* cur = &root;
    JsonPath path;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        const std::string& seg = segments[i];
        const bool last = i + 1 == segments.size();
        if (cur->is_null()) *cur = Json::object();
        if (cur->is_object()) {
            path = path.key(seg);
            if (!last && !cur->contains(seg)) (*cur)[seg] = Json::object();
            cur = &(*cur)[seg];
        } else if (cur->is_array()) {
            const bool digits = seg.size() < 10 &&
                                std::all_of(seg.begin(), seg.end(), [](char c) { return c >= '0' && c <= '9'; });
            if (!digits) throw error(&path, "is an array; expected an element index, got '" + seg + "'");
            const std::size_t index = std::stoul(seg);
            if (index >= cur->size()) {
                const JsonPath at = path.index(index);
                const std::size_t n = cur->size();
                throw error(&at, "index " + seg + " is past the end of " + path.display() + " (" +
                                     std::to_string(n) + (n == 1 ? " element)" : " elements)"));
            }
            path = path.index(index);
            cur = &(*cur)[index];
        } else {
            throw error(&path, "is a " + typeOf(*cur) + ", so it cannot contain '" + seg + "'");
        }
    }
    *cur = std::move(value);
    return AppliedOverride{path.pointer(), text};
}

} // namespace raylab::scenefmt
