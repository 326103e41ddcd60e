#include "scene/json_path.h"

#include "scene/json_locator.h"

#include <algorithm>
#include <cctype>

namespace raylab::scenefmt {
namespace {

// Messages stay short whatever the document holds: deep paths are cut in the middle.
constexpr std::size_t kShownSegments = 12;   // half before the cut, half after

bool isPlainName(std::string_view s) {
    if (s.empty()) return false;
    return std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
}

} // namespace

std::string shortText(std::string_view text) {
    constexpr std::size_t kShown = 40;
    if (text.size() <= kShown) return std::string(text);
    std::size_t cut = kShown - 3;
    while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;   // whole UTF-8 characters
    return std::string(text.substr(0, cut)) + "...";
}

JsonPath JsonPath::key(std::string_view k) const {
    JsonPath p = *this;
    p.segments.push_back({std::string(k), false});
    return p;
}

JsonPath JsonPath::index(std::size_t i) const {
    JsonPath p = *this;
    p.segments.push_back({std::to_string(i), true});
    return p;
}

std::string JsonPath::pointer() const {
    std::string out;
    for (const Segment& s : segments) out += "/" + JsonLocator::escapeToken(s.token);
    return out;
}

std::string JsonPath::display() const {
    if (segments.empty()) return "(top level)";
    std::string out;
    for (std::size_t i = 0; i < segments.size(); ++i) {
        if (segments.size() > kShownSegments && i == kShownSegments / 2) {
            const std::size_t skipped = segments.size() - kShownSegments;
            out += "...(" + std::to_string(skipped) + " levels)...";
            i += skipped - 1;
            continue;
        }
        const Segment& s = segments[i];
        const std::string token = shortText(s.token);
        if (s.index) {
            out += "[" + token + "]";
        } else if (isPlainName(token)) {
            if (!out.empty() && out.back() != '.') out += ".";
            out += token;
        } else {
            // Quoted, e.g. materials["my lamp"]; bytes that are not UTF-8 (from a --set) become U+FFFD.
            out += "[" + Json(token).dump(-1, ' ', false, Json::error_handler_t::replace) + "]";
        }
    }
    return out;
}

JsonPath pathFromPointer(const Json& doc, std::string_view pointer) {
    JsonPath p;
    const Json* cur = &doc;
    std::size_t pos = 0;
    while (pos < pointer.size()) {
        const std::size_t next = pointer.find('/', pos + 1);
        const std::string_view raw =
            pointer.substr(pos + 1, next == std::string_view::npos ? std::string_view::npos : next - pos - 1);
        std::string token;  // RFC 6901 unescaping: "~1" -> '/', "~0" -> '~'
        for (std::size_t i = 0; i < raw.size(); ++i) {
            if (raw[i] == '~' && i + 1 < raw.size()) {
                token += raw[i + 1] == '1' ? '/' : '~';
                ++i;
            } else {
                token += raw[i];
            }
        }
        if (cur && cur->is_array()) {
            const std::size_t index = std::stoul(token);
            p = p.index(index);
            cur = index < cur->size() ? &(*cur)[index] : nullptr;
        } else {
            p = p.key(token);
            cur = (cur && cur->is_object() && cur->contains(token)) ? &(*cur)[token] : nullptr;
        }
        if (next == std::string_view::npos) break;
        pos = next;
    }
    return p;
}

bool isPointerPrefix(std::string_view prefix, std::string_view pointer) {
    return pointer == prefix ||
           (pointer.size() > prefix.size() && pointer.substr(0, prefix.size()) == prefix &&
            pointer[prefix.size()] == '/');
}

std::string typeOf(const Json& v) {
    switch (v.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::boolean: return "boolean";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return "number";
    case Json::value_t::string: return v.get_ref<const std::string&>().empty() ? "empty string" : "string";
    case Json::value_t::array: return "array";
    case Json::value_t::object: return "object";
    default: return "unsupported value";
    }
}

} // namespace raylab::scenefmt
