#pragma once
// Source positions for a JSON text. nlohmann::json keeps no positions after a successful parse, so
// semantic errors ("radius must be > 0") would have no line:column. JsonLocator scans the same text
// once and maps the JSON pointer of every value ("/objects/2/radius", RFC 6901 escaping) to where the
// value starts and, for object members, where its key starts. It understands // and /* */ comments
// (as nlohmann's ignore_comments does) and a leading UTF-8 byte-order mark.
#include <cstddef>
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
    std::size_t size() const { return locations_.size(); }

    // RFC 6901: '~' -> "~0", '/' -> "~1".
    static std::string escapeToken(std::string_view token);

private:
    class Scanner;
    std::string text_;
    std::vector<std::size_t> lineStarts_;
    std::unordered_map<std::string, ValueLocation> locations_;
    std::vector<Duplicate> duplicates_;
    bool complete_ = false;
};

} // namespace raylab
