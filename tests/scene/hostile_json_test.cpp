// Hostile scene texts: nesting past the depth limit, text after the document, NUL bytes, huge keys.
// Each gives a located error with a short path, quickly, and never a crash.
#include "scene/json_parse.h"
#include "scene/scene_loader.h"

#include "support/scene_errors.h"

#include <gtest/gtest.h>

#include <string>

using namespace raylab;

namespace {

std::string errorOf(const std::string& text, const std::vector<std::string>& overrides = {}) {
    return test::sceneErrorOf(text, overrides);
}

std::string nested(std::size_t depth, const std::string& inner = "") {
    return std::string(depth, '[') + inner + std::string(depth, ']');
}

std::string repeated(const std::string& part, std::size_t n) {
    std::string out;
    for (std::size_t i = 0; i < n; ++i) out += part;
    return out;
}

const std::string kDepthLimit = std::to_string(scenefmt::kMaxJsonDepth);

} // namespace

TEST(HostileJson, NestingPastTheLimitIsALocatedErrorWithAShortPath) {
    const std::size_t limit = scenefmt::kMaxJsonDepth;
    // At the limit a value still parses (and then fails validation as an ordinary wrong type).
    EXPECT_EQ(errorOf("{ \"objects\": " + nested(limit - 1) + " }"),
              "test.json:1:15: error: objects[0]: expected an object { \"type\": \"sphere\", ... }, got array")
        << "64 levels counting the top-level object are allowed";
    // One more level is refused where it opens, naming the limit.
    EXPECT_EQ(errorOf("{ \"objects\": " + nested(limit) + " }"),
              "test.json:1:" + std::to_string(13 + limit) + ": error: objects[0][0][0][0][0]...(" +
                  std::to_string(limit - 12) + " levels)...[0][0][0][0][0][0]: nested too deeply: more than " +
                  kDepthLimit + " levels of arrays and objects");
    // Brackets inside strings and comments do not count.
    const std::string quoted = "{ \"x[\": \"" + std::string(200, '[') + "\", /* " + std::string(200, '{') +
                               " */ \"objects\": [ {} ] }";
    EXPECT_EQ(errorOf(quoted), "test.json:1:3: error: [\"x[\"]: unknown key 'x[' at the top level (known keys: camera, "
                               "render, sky, ao, materials, objects, lights)");
}

TEST(HostileJson, AHundredThousandLevelsFailWithoutCrashingWhereTheLimitIsPassed) {
    for (const std::string& text :
         {nested(100000), "{\"objects\": [{\"type\": \"sphere\", \"transform\": " + nested(100000) + "}]}",
          "{\"objects\": " + nested(100000, "1e999") + "}", repeated("{\"a\": ", 100000)}) {
        const std::string message = errorOf(text);
        EXPECT_NE(message.find("nested too deeply: more than " + kDepthLimit + " levels"), std::string::npos)
            << message.substr(0, 300);
        EXPECT_LT(message.size(), 300u) << "the path in the message is cut short";
    }
    // The parser stops at the first bracket past the limit, so its work does not grow with the depth
    // beyond it: 1,000 and 100,000 levels give the same error at the same column.
    EXPECT_EQ(errorOf(nested(100000)), errorOf(nested(1000)));
    EXPECT_EQ(errorOf(nested(100000)).rfind("test.json:1:" + std::to_string(scenefmt::kMaxJsonDepth + 1) + ":", 0), 0u)
        << errorOf(nested(100000)).substr(0, 300);
}

TEST(HostileJson, AnOverrideCannotNestPastTheLimit) {
    std::string key = "objects.0";
    for (std::size_t i = 0; i < scenefmt::kMaxJsonDepth; ++i) key += ".a";
    EXPECT_EQ(errorOf("{ \"objects\": [ {} ] }", {key + "=1"}),
              "--set " + key + "=1: error: the key has " + std::to_string(scenefmt::kMaxJsonDepth + 2) +
                  " parts; a scene nests at most " + kDepthLimit + " levels");
    EXPECT_NE(errorOf("{ \"objects\": [ {} ] }", {"render.spp=" + nested(100000)}).find("nested too deeply"),
              std::string::npos);
}

TEST(HostileJson, TextAfterTheDocumentIsAnErrorAtItsPlace) {
    const std::string doc = "{ \"objects\": [ {} ] }";
    EXPECT_EQ(errorOf(doc + "\n  x"), "test.json:2:3: error: unexpected text after the end of the document (only "
                                      "whitespace and comments may follow it)");
    EXPECT_EQ(errorOf(doc + " [1]"), "test.json:1:23: error: unexpected text after the end of the document (only "
                                     "whitespace and comments may follow it)");
    EXPECT_LT(errorOf(doc + std::string(100000, ' ') + "x").size(), 200u) << "the parser's 'last read' is not quoted";
    EXPECT_EQ(errorOf(doc + "\n// a comment\n/* another */\n"), "<no error>");
    // A comment left open says so where it opens, after the document or inside it.
    EXPECT_EQ(errorOf(doc + "\n  /* never closed\n"),
              "test.json:2:3: error: a /* comment is never closed (no */ before the end of the file)");
    EXPECT_EQ(errorOf("{ \"objects\": [ {} ] /* open"),
              "test.json:1:21: error: a /* comment is never closed (no */ before the end of the file)");
}

TEST(HostileJson, ANulByteAnywhereIsAnErrorAtItsPlace) {
    const std::string doc = "{ \"objects\": [ {} ] }";
    const std::string nul(1, '\0');
    EXPECT_EQ(errorOf(doc + nul + "garbage"), "test.json:1:22: error: unexpected NUL byte (a scene file is text)");
    EXPECT_EQ(errorOf(doc + "\n" + nul), "test.json:2:1: error: unexpected NUL byte (a scene file is text)");
    EXPECT_EQ(errorOf("// comment " + nul + "\n" + doc), "test.json:1:12: error: unexpected NUL byte (a scene file is text)");
    EXPECT_EQ(errorOf("{ \"objects\": " + nul + "[ {} ] }"),
              "test.json:1:14: error: unexpected NUL byte (a scene file is text)");
    // Inside a string the parser's own complaint stands.
    EXPECT_NE(errorOf("{ \"obj" + nul + "ects\": [ {} ] }").find("test.json:1:7: error: syntax error while parsing "
                                                                 "object key - invalid string: control character "
                                                                 "U+0000 (NUL)"),
              std::string::npos)
        << errorOf("{ \"obj" + nul + "ects\": [ {} ] }");
}

TEST(HostileJson, LongKeysAndLongLastReadTokensAreCutShort) {
    const std::string key(100000, 'k');
    const std::string message = errorOf("{ \"" + key + "\": 1, \"objects\": [ {} ] }");
    EXPECT_LT(message.size(), 400u) << message.substr(0, 400);
    EXPECT_NE(message.find("kkk...\"]: unknown key 'kkk"), std::string::npos) << message.substr(0, 400);
    const std::string literal = errorOf("{ \"objects\": [ { \"radius\": tru" + std::string(100000, 'e') + " } ] }");
    EXPECT_LT(literal.size(), 200u) << literal.substr(0, 400);
}
