#include "scene/json_locator.h"

#include "scene/json_parse.h"

#include <algorithm>
#include <cstdint>

namespace raylab {
namespace {

bool startsWithBom(std::string_view t) {
    return t.size() >= 3 && static_cast<unsigned char>(t[0]) == 0xEF &&
           static_cast<unsigned char>(t[1]) == 0xBB && static_cast<unsigned char>(t[2]) == 0xBF;
}

void appendUtf8(std::string& out, std::uint32_t cp) {
    if (cp < 0x80) {
        out += static_cast<char>(cp);
    } else if (cp < 0x800) {
        out += static_cast<char>(0xC0 | (cp >> 6));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
        out += static_cast<char>(0xE0 | (cp >> 12));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (cp >> 18));
        out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (cp & 0x3F));
    }
}

} // namespace

// Recursive-descent scanner over JSON with comments (RFC 8259 grammar). It does not check numbers
// or literals in detail: the text has normally been accepted by nlohmann already, and all we need is
// where each value and key starts.
class JsonLocator::Scanner {
public:
    Scanner(JsonLocator& out, std::string_view text) : out_(out), t_(text) {}

    bool run() {
        if (startsWithBom(t_)) pos_ = cursor_ = 3;   // the BOM takes no column
        if (!skipSpace()) return false;
        if (!value(kNoParent, {}, SourcePos{}, 0)) return false;
        if (!skipSpace()) return false;
        return pos_ == t_.size();
    }

private:
    bool atEnd() const { return pos_ >= t_.size(); }
    char peek(std::size_t ahead = 0) const { return pos_ + ahead < t_.size() ? t_[pos_ + ahead] : '\0'; }

    // Whitespace and comments.
    bool skipSpace() {
        while (!atEnd()) {
            const char c = peek();
            if (c == ' ' || c == '\t' || c == '\n' || c == '\r') {
                ++pos_;
            } else if (c == '/' && peek(1) == '/') {
                while (!atEnd() && peek() != '\n') ++pos_;
            } else if (c == '/' && peek(1) == '*') {
                const std::size_t close = t_.find("*/", pos_ + 2);
                if (close == std::string_view::npos) return false;
                pos_ = close + 2;
            } else {
                break;
            }
        }
        return true;
    }

    // Line and column of an offset at or after the last one asked for: each byte is counted once,
    // so a long single-line file is located in linear time.
    SourcePos at(std::size_t offset) {
        for (; cursor_ < offset && cursor_ < t_.size(); ++cursor_) {
            if (t_[cursor_] == '\n') {
                ++cursorPos_.line;
                cursorPos_.column = 1;
            } else if ((static_cast<unsigned char>(t_[cursor_]) & 0xC0) != 0x80) {
                ++cursorPos_.column;   // UTF-8 continuation bytes take no column
            }
        }
        return cursorPos_;
    }

    // The node of the value at valueOffset; a repeated key's value is recorded as a duplicate and
    // gets a node of its own that find() never returns.
    std::uint32_t record(std::uint32_t parent, std::string&& token, SourcePos key, std::size_t valueOffset) {
        const auto node = static_cast<std::uint32_t>(out_.nodes_.size());
        out_.nodes_.push_back(Node{ValueLocation{at(valueOffset), key}, parent, nullptr});
        if (parent == kNoParent) return node;
        auto [it, inserted] = out_.children_.emplace(ChildKey{parent, std::move(token)}, node);
        out_.nodes_[node].token = &it->first.token;
        if (!inserted)
            out_.duplicates_.push_back(Duplicate{out_.pointerOf(it->second), out_.nodes_[it->second].location.key, key});
        return node;
    }

    bool value(std::uint32_t parent, std::string&& token, SourcePos key, int depth) {
        if (atEnd()) return false;
        if (depth > int(scenefmt::kMaxJsonDepth)) return false;   // the parser refuses it too
        const std::uint32_t node = record(parent, std::move(token), key, pos_);
        switch (peek()) {
        case '{': return object(node, depth);
        case '[': return array(node, depth);
        case '"': return string(nullptr);
        default: return scalar();
        }
    }

    bool object(std::uint32_t node, int depth) {
        ++pos_;  // '{'
        if (!skipSpace()) return false;
        if (peek() == '}') {
            ++pos_;
            return true;
        }
        while (true) {
            if (!skipSpace() || peek() != '"') return false;
            const SourcePos keyPos = at(pos_);
            std::string name;
            if (!string(&name)) return false;
            if (!skipSpace() || peek() != ':') return false;
            ++pos_;
            if (!skipSpace()) return false;
            if (!value(node, std::move(name), keyPos, depth + 1)) return false;
            if (!skipSpace()) return false;
            if (peek() == ',') {
                ++pos_;
                continue;
            }
            if (peek() == '}') {
                ++pos_;
                return true;
            }
            return false;
        }
    }

    bool array(std::uint32_t node, int depth) {
        ++pos_;  // '['
        if (!skipSpace()) return false;
        if (peek() == ']') {
            ++pos_;
            return true;
        }
        for (std::size_t index = 0;; ++index) {
            if (!skipSpace()) return false;
            if (!value(node, std::to_string(index), SourcePos{}, depth + 1)) return false;
            if (!skipSpace()) return false;
            if (peek() == ',') {
                ++pos_;
                continue;
            }
            if (peek() == ']') {
                ++pos_;
                return true;
            }
            return false;
        }
    }

    // Numbers, true, false, null: everything up to the next delimiter.
    bool scalar() {
        const std::size_t start = pos_;
        while (!atEnd()) {
            const char c = peek();
            if (c == ',' || c == ']' || c == '}' || c == ':' || c == ' ' || c == '\t' || c == '\n' ||
                c == '\r' || c == '/' || c == '"' || c == '[' || c == '{')
                break;
            ++pos_;
        }
        return pos_ > start;
    }

    bool hex4(std::uint32_t& out) {
        out = 0;
        for (int i = 0; i < 4; ++i) {
            const char c = peek();
            std::uint32_t d = 0;
            if (c >= '0' && c <= '9') d = static_cast<std::uint32_t>(c - '0');
            else if (c >= 'a' && c <= 'f') d = static_cast<std::uint32_t>(c - 'a' + 10);
            else if (c >= 'A' && c <= 'F') d = static_cast<std::uint32_t>(c - 'A' + 10);
            else return false;
            out = out * 16 + d;
            ++pos_;
        }
        return true;
    }

    // A string starting at '"'; decodes escapes into *decoded when given (keys must match nlohmann's).
    bool string(std::string* decoded) {
        ++pos_;  // opening quote
        while (!atEnd()) {
            const char c = peek();
            if (c == '"') {
                ++pos_;
                return true;
            }
            if (static_cast<unsigned char>(c) < 0x20) return false;  // raw control character
            if (c != '\\') {
                if (decoded) *decoded += c;
                ++pos_;
                continue;
            }
            ++pos_;  // backslash
            const char e = peek();
            ++pos_;
            char plain = '\0';
            switch (e) {
            case '"': plain = '"'; break;
            case '\\': plain = '\\'; break;
            case '/': plain = '/'; break;
            case 'b': plain = '\b'; break;
            case 'f': plain = '\f'; break;
            case 'n': plain = '\n'; break;
            case 'r': plain = '\r'; break;
            case 't': plain = '\t'; break;
            case 'u': {
                std::uint32_t cp = 0;
                if (!hex4(cp)) return false;
                // UTF-16 surrogate pair (RFC 8259 section 7): \uD8xx\uDCxx encodes one code point.
                if (cp >= 0xD800 && cp <= 0xDBFF && peek() == '\\' && peek(1) == 'u') {
                    const std::size_t save = pos_;
                    pos_ += 2;
                    std::uint32_t low = 0;
                    if (hex4(low) && low >= 0xDC00 && low <= 0xDFFF) {
                        cp = 0x10000 + ((cp - 0xD800) << 10) + (low - 0xDC00);
                    } else {
                        pos_ = save;
                    }
                }
                if (decoded) appendUtf8(*decoded, cp);
                continue;
            }
            default: return false;
            }
            if (decoded) *decoded += plain;
        }
        return false;  // unterminated
    }

    JsonLocator& out_;
    std::string_view t_;
    std::size_t pos_ = 0;
    std::size_t cursor_ = 0;             // at(): the offset cursorPos_ belongs to
    SourcePos cursorPos_{1, 1};
};

JsonLocator::JsonLocator(std::string_view text) : text_(text) {
    lineStarts_.push_back(0);
    for (std::size_t i = 0; i < text_.size(); ++i)
        if (text_[i] == '\n') lineStarts_.push_back(i + 1);
    Scanner scanner(*this, text_);
    complete_ = scanner.run();
}

std::size_t JsonLocator::ChildKeyHash::operator()(const ChildKey& k) const noexcept {
    return std::hash<std::string>{}(k.token) ^ (std::size_t(k.parent) * 0x9E3779B97F4A7C15ull);
}

// RFC 6901: tokens separated by '/', with "~1" for '/' and "~0" for '~'.
const ValueLocation* JsonLocator::find(std::string_view pointer) const {
    if (nodes_.empty()) return nullptr;
    if (pointer.empty()) return &nodes_[0].location;
    if (pointer.front() != '/') return nullptr;
    std::uint32_t node = 0;
    ChildKey key{0, {}};
    while (!pointer.empty()) {
        pointer.remove_prefix(1);   // '/'
        const std::size_t end = std::min(pointer.find('/'), pointer.size());
        key.parent = node;
        key.token.clear();
        for (std::size_t i = 0; i < end; ++i) {
            if (pointer[i] == '~' && i + 1 < end && (pointer[i + 1] == '0' || pointer[i + 1] == '1')) {
                key.token += pointer[i + 1] == '0' ? '~' : '/';
                ++i;
            } else {
                key.token += pointer[i];
            }
        }
        const auto it = children_.find(key);
        if (it == children_.end()) return nullptr;
        node = it->second;
        pointer.remove_prefix(end);
    }
    return &nodes_[node].location;
}

std::string JsonLocator::pointerOf(std::uint32_t node) const {
    std::vector<const std::string*> tokens;
    for (; node != kNoParent && nodes_[node].parent != kNoParent; node = nodes_[node].parent)
        tokens.push_back(nodes_[node].token);
    std::string out;
    for (auto t = tokens.rbegin(); t != tokens.rend(); ++t) out += "/" + escapeToken(**t);
    return out;
}

SourcePos JsonLocator::position(std::size_t byteOffset) const {
    byteOffset = std::min(byteOffset, text_.size());
    const auto next = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), byteOffset);
    const std::size_t line = static_cast<std::size_t>(next - lineStarts_.begin());  // 1-based
    std::size_t start = lineStarts_[line - 1];
    if (start == 0 && startsWithBom(text_) && byteOffset >= 3) start = 3;  // the BOM takes no column
    int column = 1;
    for (std::size_t i = start; i < byteOffset; ++i)
        if ((static_cast<unsigned char>(text_[i]) & 0xC0) != 0x80) ++column;  // skip UTF-8 continuation bytes
    return SourcePos{static_cast<int>(line), column};
}

std::string JsonLocator::escapeToken(std::string_view token) {
    std::string out;
    out.reserve(token.size());
    for (char c : token) {
        if (c == '~') out += "~0";
        else if (c == '/') out += "~1";
        else out += c;
    }
    return out;
}

} // namespace raylab
