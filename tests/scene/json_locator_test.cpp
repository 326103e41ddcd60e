// JsonLocator: JSON pointer -> line:column of values and keys, on inputs built to confuse a scanner.
#include "scene/json_locator.h"

#include <gtest/gtest.h>

#include <malloc.h>

#include <string>

using namespace raylab;

namespace {

// "line:column" of a value (or of its key), "-" when not found.
std::string valueAt(const JsonLocator& l, const std::string& pointer) {
    const ValueLocation* loc = l.find(pointer);
    if (!loc) return "-";
    return std::to_string(loc->value.line) + ":" + std::to_string(loc->value.column);
}
std::string keyAt(const JsonLocator& l, const std::string& pointer) {
    const ValueLocation* loc = l.find(pointer);
    if (!loc || !loc->key.valid()) return "-";
    return std::to_string(loc->key.line) + ":" + std::to_string(loc->key.column);
}

} // namespace

TEST(SceneLocator, ValuesAndKeysOfNestedObjects) {
    const std::string text = "{\n"
                             "  \"camera\": { \"fov\": 40 },\n"
                             "  \"objects\": [\n"
                             "    { \"radius\": 1 },\n"
                             "    {\"radius\":2.5}\n"
                             "  ]\n"
                             "}\n";
    const JsonLocator l(text);
    EXPECT_TRUE(l.complete());
    EXPECT_EQ(valueAt(l, ""), "1:1");
    EXPECT_EQ(keyAt(l, ""), "-");
    EXPECT_EQ(valueAt(l, "/camera"), "2:13");
    EXPECT_EQ(keyAt(l, "/camera"), "2:3");
    EXPECT_EQ(valueAt(l, "/camera/fov"), "2:22");
    EXPECT_EQ(keyAt(l, "/camera/fov"), "2:15");
    EXPECT_EQ(valueAt(l, "/objects"), "3:14");
    EXPECT_EQ(valueAt(l, "/objects/0"), "4:5");
    EXPECT_EQ(keyAt(l, "/objects/0"), "-") << "array elements have no key";
    EXPECT_EQ(valueAt(l, "/objects/0/radius"), "4:17");
    EXPECT_EQ(valueAt(l, "/objects/1/radius"), "5:15");
    EXPECT_EQ(keyAt(l, "/objects/1/radius"), "5:6");
    EXPECT_EQ(valueAt(l, "/objects/2"), "-");
    EXPECT_EQ(valueAt(l, "/camera/fo"), "-");
    EXPECT_EQ(l.size(), 8u);
}

TEST(SceneLocator, StringsWithBracesQuotesAndEscapes) {
    // Braces, brackets, commas, colons, escaped quotes and backslashes inside strings are text.
    const std::string text = R"({"a": "}{][,:\"", "b\"}": "\\", "c": "\\\"{", "d": [ "]", "\u005d" ], "e": 7})";
    const JsonLocator l(text);
    EXPECT_TRUE(l.complete());
    EXPECT_EQ(valueAt(l, "/a"), "1:7");
    EXPECT_EQ(valueAt(l, "/b\"}"), "1:27") << "key with an escaped quote and a brace";
    EXPECT_EQ(keyAt(l, "/b\"}"), "1:19");
    EXPECT_EQ(valueAt(l, "/c"), "1:38");
    EXPECT_EQ(valueAt(l, "/d/0"), "1:54");
    EXPECT_EQ(valueAt(l, "/d/1"), "1:59");
    EXPECT_EQ(valueAt(l, "/e"), "1:76");
    EXPECT_EQ(l.size(), 8u);
}

TEST(SceneLocator, KeysAreDecodedAndEscapedAsJsonPointers) {
    // \u0061 is 'a'; a surrogate pair is one code point (U+1F600, 4 UTF-8 bytes); '/' and '~' in keys
    // become ~1 and ~0 (RFC 6901).
    const std::string text = R"({"r\u0061dius": 1, "\ud83d\ude00": 2, "a/b": 3, "m~n": 4, "tab\t": 5})";
    const JsonLocator l(text);
    EXPECT_TRUE(l.complete());
    EXPECT_EQ(valueAt(l, "/radius"), "1:17");
    EXPECT_EQ(valueAt(l, "/\xF0\x9F\x98\x80"), "1:36");
    EXPECT_EQ(valueAt(l, "/a~1b"), "1:46");
    EXPECT_EQ(valueAt(l, "/m~0n"), "1:56");
    EXPECT_EQ(valueAt(l, "/tab\t"), "1:68");
    EXPECT_EQ(JsonLocator::escapeToken("a/b~c"), "a~1b~0c");
}

TEST(SceneLocator, CommentsAreSkippedEvenWhenTheyLookLikeJson) {
    const std::string text = "// { \"fake\": [ \"\n"
                             "{ /* \"a\": 1, } ] */ \"a\": // \"a\": 2\n"
                             "    [1, /* ] */ 2], \"b\": \"//not a comment\", \"c\" /* x */ : /**/3 }\n";
    const JsonLocator l(text);
    EXPECT_TRUE(l.complete());
    EXPECT_EQ(valueAt(l, ""), "2:1");
    EXPECT_EQ(keyAt(l, "/a"), "2:21");
    EXPECT_EQ(valueAt(l, "/a"), "3:5");
    EXPECT_EQ(valueAt(l, "/a/1"), "3:17");
    EXPECT_EQ(valueAt(l, "/b"), "3:26");
    EXPECT_EQ(valueAt(l, "/c"), "3:63");
    EXPECT_EQ(valueAt(l, "/fake"), "-");
    EXPECT_EQ(l.size(), 6u);
}

TEST(SceneLocator, NestedArraysAndEmptyContainers) {
    const std::string text = "[[], [[1, [2, 3]], {}], {\"k\": [[], [4]]}, [[[[\"deep\"]]]]]";
    const JsonLocator l(text);
    EXPECT_TRUE(l.complete());
    EXPECT_EQ(valueAt(l, "/0"), "1:2");
    EXPECT_EQ(valueAt(l, "/1/0/1/1"), "1:15");
    EXPECT_EQ(valueAt(l, "/1/1"), "1:20");
    EXPECT_EQ(valueAt(l, "/2/k/1/0"), "1:37");
    EXPECT_EQ(valueAt(l, "/3/0/0/0/0"), "1:47");
    EXPECT_EQ(valueAt(l, "/0/0"), "-");
}

TEST(SceneLocator, ColumnsCountCharactersAndLinesAnyEnding) {
    // é is two bytes, € three; a tab is one column; CRLF ends a line; a BOM takes no column.
    const std::string text = "\xEF\xBB\xBF{\"\xC3\xA9\xE2\x82\xAC\":\t1,\r\n \"b\": 2}";
    const JsonLocator l(text);
    EXPECT_TRUE(l.complete());
    EXPECT_EQ(valueAt(l, ""), "1:1");
    EXPECT_EQ(valueAt(l, "/\xC3\xA9\xE2\x82\xAC"), "1:8");
    EXPECT_EQ(valueAt(l, "/b"), "2:7");
    EXPECT_EQ(l.position(0), (SourcePos{1, 1}));
    EXPECT_EQ(l.position(text.size()), (SourcePos{2, 9}));
    EXPECT_EQ(l.position(text.size() + 100), (SourcePos{2, 9})) << "past the end clamps";
}

TEST(SceneLocator, DuplicateKeysAreReported) {
    const JsonLocator l("{\"a\": {\"x\": 1,\n \"x\": 2}, \"b\": 3}");
    ASSERT_EQ(l.duplicates().size(), 1u);
    EXPECT_EQ(l.duplicates()[0].pointer, "/a/x");
    EXPECT_EQ(l.duplicates()[0].first, (SourcePos{1, 8}));
    EXPECT_EQ(l.duplicates()[0].second, (SourcePos{2, 2}));
    EXPECT_EQ(valueAt(l, "/a/x"), "1:13") << "find() reports the first occurrence";
}

TEST(SceneLocator, BrokenInputKeepsWhatWasFoundAndNeverCrashes) {
    const JsonLocator l("{\"a\": 1, \"b\": [2, ");
    EXPECT_FALSE(l.complete());
    EXPECT_EQ(valueAt(l, "/a"), "1:7");
    EXPECT_EQ(valueAt(l, "/b/0"), "1:16");
    for (const char* bad : {"", "{", "}", "\"unterminated", "{\"a\" 1}", "[1,,2]", "/* open", "{\"a\": \"\\u12\"}",
                            "[1] [2]", "{\"a\":\n\"line\nbreak\"}"}) {
        const JsonLocator b(bad);
        EXPECT_FALSE(b.complete()) << bad;
    }
    // Very deep nesting is cut off, not a stack overflow.
    const std::string deep = std::string(100000, '[') + std::string(100000, ']');
    const JsonLocator d(deep);
    EXPECT_FALSE(d.complete());
    EXPECT_EQ(valueAt(d, "/0/0"), "1:3");
}

// A long key over many values: each value's place is a (parent, token) node, so the locator's heap
// grows with the text: about 130 bytes a value (a node and its hash entry), here 7 characters each.
// Storing a full pointer string per value took key length × value count (here 200 MB for a 139 kB
// text). glibc's mallinfo2 counts the bytes; a sanitizer's allocator reports none.
TEST(SceneLocator, MemoryIsLinearInTheTextForLongKeysOverManyValues) {
    const std::string key(10000, 'k');
    std::string text = "{\"" + key + "\": [";
    for (int i = 0; i < 20000; ++i) text += (i ? ", " : "") + std::to_string(i);
    text += "]}";
    const std::size_t before = mallinfo2().uordblks;
    const JsonLocator l(text);
    const std::size_t used = mallinfo2().uordblks - before;
    if (used == 0) GTEST_SKIP() << "the allocator reports no usage (sanitizer build)";
    ASSERT_TRUE(l.complete());
    EXPECT_EQ(l.size(), 20002u);
    EXPECT_EQ(valueAt(l, "/" + key + "/19999"), "1:" + std::to_string(text.size() - 6));
    EXPECT_LT(used, 32 * text.size()) << "bytes held for a " << text.size() << "-byte text";
}

TEST(SceneLocator, PointersWithEscapedTokensAndMissingPlaces) {
    const JsonLocator l(R"({"a/b": {"~c": [0, {"": 5}]}})");
    EXPECT_EQ(valueAt(l, ""), "1:1");
    EXPECT_EQ(valueAt(l, "/a~1b/~0c/1/"), "1:25");
    EXPECT_EQ(valueAt(l, "/a/b"), "-");
    EXPECT_EQ(valueAt(l, "a~1b"), "-");
    EXPECT_EQ(valueAt(l, "/a~1b/~0c/2"), "-");
    EXPECT_EQ(valueAt(l, "/a~1b/~0c/0/x"), "-");
}
