#include "scene/json_path.h"

#include "scene/json_locator.h"

#include <algorithm>
#include <cctype>

namespace raylab::scenefmt {
namespace {

bool isPlainName(std::string_view s) {
    if (s.empty()) return false;
    return std::all_of(s.begin(), s.end(), [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
}

} // namespace

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
    for (const Segment& s : segments) {
        if (s.index) {
            out += "[" + s.token + "]";
        } else if (isPlainName(s.token)) {
            if (!out.empty()) out += ".";
            out += s.token;
        } else {
            out += "[" + Json(s.token).dump() + "]";  // quoted, e.g. materials["my lamp"]
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
    case Json::value_t::string: return "string";
    case Json::value_t::array: return "array";
    case Json::value_t::object: return "object";
    default: return "unsupported value";
    }
}

} // namespace raylab::scenefmt
