#include "scene/json_parse.h"

#include <string>
#include <utility>
#include <vector>

namespace raylab::scenefmt {
namespace {

constexpr const char* kUnclosedComment = "a /* comment is never closed (no */ before the end of the file)";

class DomBuilder : public nlohmann::json_sax<Json> {
public:
    ParseResult result;
    bool tooDeep = false;   // the parse stopped at a container past kMaxJsonDepth

    bool null() override { return add(Json(nullptr)); }
    bool boolean(bool v) override { return add(Json(v)); }
    bool number_integer(number_integer_t v) override { return add(Json(v)); }
    bool number_unsigned(number_unsigned_t v) override { return add(Json(v)); }
    bool number_float(number_float_t v, const string_t&) override { return add(Json(v)); }
    bool string(string_t& v) override { return add(Json(std::move(v))); }
    bool binary(binary_t& v) override { return add(Json::binary(std::move(v))); }
    bool start_object(std::size_t) override { return open(Json::object()); }
    bool key(string_t& k) override {
        stack_.back().key = k;
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(Json::array()); }
    bool end_array() override { return close(); }

    bool parse_error(std::size_t position, const std::string& lastToken,
                     const nlohmann::detail::exception& ex) override {
        result.ok = false;
        // `position` counts the characters read, so position - 1 is the offending character.
        result.errorOffset = position > 0 ? position - 1 : 0;
        if (ex.id == 406) {  // out_of_range.406: a number overflows a double (e.g. 1e999)
            result.errorOffset = position >= lastToken.size() ? position - lastToken.size() : 0;
            result.reason = "must be finite, got " + lastToken + " (too large for a double)";
            result.errorPath = currentPath();
        } else if (std::string_view(ex.what()).find("missing closing '*/'") != std::string_view::npos) {
            result.reason = kUnclosedComment;   // parseJson places it where the comment opens
        } else if (std::string_view(ex.what()).ends_with("expected end of input")) {
            result.reason = "unexpected text after the end of the document (only whitespace and comments may follow it)";
        } else {
            result.reason = shortenLastRead(stripPrefix(ex.what()));
        }
        return false;
    }

private:
    struct Level {
        Json* container;
        std::string key;  // objects: the key of the value that comes next
    };

    Json* place(Json&& v) {
        if (stack_.empty()) {
            result.doc = std::move(v);
            return &result.doc;
        }
        Level& top = stack_.back();
        if (top.container->is_array()) {
            top.container->push_back(std::move(v));
            return &top.container->back();
        }
        Json& slot = (*top.container)[top.key];
        slot = std::move(v);
        return &slot;
    }
    bool add(Json&& v) {
        place(std::move(v));
        return true;
    }
    bool open(Json&& v) {
        if (stack_.size() >= kMaxJsonDepth) {
            tooDeep = true;
            result.ok = false;
            result.reason = "nested too deeply: more than " + std::to_string(kMaxJsonDepth) +
                            " levels of arrays and objects";
            result.errorPath = currentPath();
            return false;
        }
        stack_.push_back(Level{place(std::move(v)), {}});
        return true;
    }
    bool close() {
        stack_.pop_back();
        return true;
    }
    JsonPath currentPath() const {
        // Enclosing arrays already hold the element being filled (the last one); the innermost
        // container has not received the offending value yet.
        JsonPath p;
        p.segments.reserve(stack_.size());
        for (std::size_t i = 0; i < stack_.size(); ++i) {
            const Json& c = *stack_[i].container;
            if (!c.is_array()) p.segments.push_back({stack_[i].key, false});
            else p.segments.push_back({std::to_string(i + 1 < stack_.size() ? c.size() - 1 : c.size()), true});
        }
        return p;
    }
    // "last read: '<everything since the previous token>'" keeps only its end, where the error is.
    static std::string shortenLastRead(std::string what) {
        constexpr std::string_view open = "last read: '";
        constexpr std::size_t kShown = 40;
        const std::size_t start = what.find(open);
        if (start == std::string::npos) return what;
        const std::size_t from = start + open.size();
        const std::size_t close = what.find("'; ", from);
        if (close == std::string::npos || close - from <= kShown) return what;
        std::size_t keep = close - kShown;
        while (keep < close && (static_cast<unsigned char>(what[keep]) & 0xC0) == 0x80) ++keep;   // whole characters
        return what.substr(0, from) + "..." + what.substr(keep);
    }
    // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ..." -> "syntax error ..."
    static std::string stripPrefix(std::string_view what) {
        if (auto bracket = what.find("] "); bracket != std::string_view::npos && what.front() == '[')
            what.remove_prefix(bracket + 2);
        if (what.starts_with("parse error")) {
            if (auto colon = what.find(": "); colon != std::string_view::npos) what.remove_prefix(colon + 2);
        }
        return std::string(what);
    }

    std::vector<Level> stack_;
};

// The last character of the string or comment that starts at text[i], i itself when none starts
// there, npos for a /* comment that is never closed.
std::size_t skipStringOrComment(std::string_view text, std::size_t i) {
    if (text[i] == '"') {
        for (++i; i < text.size() && text[i] != '"'; ++i)
            if (text[i] == '\\') ++i;
        return i;
    }
    if (text[i] != '/' || i + 1 >= text.size()) return i;
    if (text[i + 1] == '/') {
        while (i < text.size() && text[i] != '\n' && text[i] != '\r' && text[i] != '\0') ++i;
        return i;
    }
    if (text[i + 1] != '*') return i;
    const std::size_t close = text.find("*/", i + 2);
    return close == std::string_view::npos ? std::string_view::npos : close + 1;
}

// Offset of the first '[' or '{' that opens level `depth` + 1, skipping strings and comments; the
// text up to there has been accepted by the parser, so this simple scan agrees with it.
std::size_t openingPastDepth(std::string_view text, std::size_t depth) {
    std::size_t level = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const std::size_t skipped = skipStringOrComment(text, i);
        if (skipped == std::string_view::npos) break;
        if (skipped != i) {
            i = skipped;
        } else if (text[i] == '[' || text[i] == '{') {
            if (++level > depth) return i;
        } else if (text[i] == ']' || text[i] == '}') {
            --level;
        }
    }
    return text.size();
}

// Offset of the /* that is never closed (the lexer reports the end of the file instead).
std::size_t unclosedCommentAt(std::string_view text) {
    for (std::size_t i = 0; i < text.size(); ++i) {
        const std::size_t skipped = skipStringOrComment(text, i);
        if (skipped == std::string_view::npos) return i;
        i = skipped;
    }
    return text.size();
}

} // namespace

ParseResult parseJson(std::string_view text) {
    DomBuilder builder;
    builder.result.ok = true;
    const bool ok = Json::sax_parse(text.begin(), text.end(), &builder, nlohmann::json::input_format_t::json,
                                    /*strict=*/true, /*ignore_comments=*/true);
    ParseResult result = std::move(builder.result);
    result.ok = ok && result.ok;
    if (builder.tooDeep) {
        result.errorOffset = openingPastDepth(text, kMaxJsonDepth);
        return result;
    }
    if (!result.ok && result.reason == kUnclosedComment) result.errorOffset = unclosedCommentAt(text);
    // nlohmann takes a NUL byte for the end of the input, so text after one would pass unread.
    const std::size_t nul = text.find('\0');
    if (nul == std::string_view::npos) return result;
    const bool endedAtNul = nul == result.errorOffset && result.reason.find("end of input") != std::string::npos;
    if (result.ok || nul < result.errorOffset || endedAtNul) {
        result.ok = false;
        result.errorOffset = nul;
        result.reason = "unexpected NUL byte (a scene file is text)";
        result.errorPath.reset();
    }
    return result;
}

} // namespace raylab::scenefmt
