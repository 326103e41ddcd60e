#pragma once
// Source positions for a JSON text. nlohmann::json keeps no positions after a successful parse, so
// semantic errors ("radius must be > 0") would have no line:column. JsonLocator scans the same text
// once and maps the JSON pointer of every value ("/objects/2/radius", RFC 6901 escaping) to where the
// value starts and, for object members, where its key starts. It understands // and /* */ comments
// (as nlohmann's ignore_comments does) and a leading UTF-8 byte-order mark. Values are kept as a tree
// of (parent, token) nodes, so its memory grows with the text, not with the keys' depth times length.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace raylab {

// 1-based line and column; columns count Unicode code points (a tab is one column).
struct SourcePos {
    int line = 0;
    int column = 0;
    bool valid() const { return line > 0; }
    bool operator==(const SourcePos&) const = default;
};

struct ValueLocation {
    SourcePos value;   // first character of the value ('{', '[', '"', digit, 't', ...)
    SourcePos key;     // opening quote of the member's key; invalid for array elements and the root
};

class JsonLocator {
public:
    // Scans `text`. Tolerant: on a syntax error it keeps what it found up to there (complete() false).
    explicit JsonLocator(std::string_view text);

    // nullptr when the pointer names no value in the text. The root is "".
    const ValueLocation* find(std::string_view pointer) const;

    // Line and column of a byte offset into the text (offsets past the end map to just after it).
    SourcePos position(std::size_t byteOffset) const;

    // A key that occurs twice in one object (the later occurrence; find() reports the first).
    struct Duplicate {
        std::string pointer;
        SourcePos first;    // key position of the first occurrence
        SourcePos second;   // key position of the repeated one
    };
    const std::vector<Duplicate>& duplicates() const { return duplicates_; }

    bool complete() const { return complete_; }
    std::size_t size() const { return nodes_.size(); }

    // RFC 6901: '~' -> "~0", '/' -> "~1".
    static std::string escapeToken(std::string_view token);

private:
    class Scanner;
    // A child's address: its parent node and its token (an object key, decoded, or an array index).
    struct ChildKey {
        std::uint32_t parent;
        std::string token;
        bool operator==(const ChildKey&) const = default;
    };
    struct ChildKeyHash {
        std::size_t operator()(const ChildKey& k) const noexcept;
    };
    struct Node {
        ValueLocation location;
        std::uint32_t parent;        // kNoParent for the root
        const std::string* token;    // the key in children_ (stable: unordered_map nodes never move)
    };
    static constexpr std::uint32_t kNoParent = 0xffffffffu;
    std::string pointerOf(std::uint32_t node) const;

    std::string text_;
    std::vector<std::size_t> lineStarts_;
    std::vector<Node> nodes_;                                        // nodes_[0] is the root
    std::unordered_map<ChildKey, std::uint32_t, ChildKeyHash> children_;   // first occurrence wins
    std::vector<Duplicate> duplicates_;
    bool complete_ = false;
};

} // namespace raylab
