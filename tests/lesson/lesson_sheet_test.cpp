// Handouts (src/lesson/lesson_sheet.h): every shipped lesson exports a worksheet without the
// answers and a teacher's sheet with them, pictures inside the page; and md4c's Markdown becomes
// the HTML it should.
#include "lesson/data_uri.h"
#include "lesson/lesson.h"
#include "lesson/lesson_sheet.h"
#include "lesson/markdown_blocks.h"
#include "lesson/markdown_html.h"

#include "support/dutch_lesson_fixture.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstring>

#include <filesystem>
#include <fstream>
#include <string>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

const fs::path kLessons = fs::path(RAYLAB_SOURCE_DIR) / "lessons";

// Runs of white space as one space, ends trimmed.
std::string squeeze(const std::string& s) {
    std::string out;
    bool space = false;
    for (const char ch : s) {
        if (ch == ' ' || ch == '\n' || ch == '\t' || ch == '\r') {
            space = !out.empty();
            continue;
        }
        if (space) out += ' ';
        space = false;
        out += ch;
    }
    return out;
}

// The page's text as a reader sees it: tags out (inline ones join words, blocks end in a newline),
// the four escapes of the writer undone.
std::string pageText(const std::string& html) {
    std::string text;
    bool tag = false;
    for (std::size_t i = 0; i < html.size(); ++i) {
        const char ch = html[i];
        // A table's cells are apart on the page (and tab-separated in MarkdownBlock::plainText).
        const auto at = [&](const char* t) { return html.compare(i, std::strlen(t), t) == 0; };
        if (ch == '<' && (at("<td") || at("<th") || at("</td") || at("</th") || at("<tr") || at("</tr"))) text += ' ';
        if (ch == '<') tag = true;
        else if (ch == '>' && tag) tag = false;
        else if (!tag) text += ch;
    }
    for (const auto& [from, to] : {std::pair{"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&amp;", "&"}})
        for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + 1)) text.replace(at, std::string(from).size(), to);
    return squeeze(text);
}

std::size_t count(const std::string& s, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
    return n;
}

const ImageSource kNoImages = [](const std::string& src) { return "IMG(" + src + ")"; };

} // namespace

TEST(LessonSheet, PupilSheetLeavesOutEveryAnswerThatTheTeacherSheetHolds) {
    for (const Lesson& lesson : loadLessons(kLessons)) {
        SCOPED_TRACE(lesson.file.string());
        const std::string pupil = pageText(lessonSheetHtml(lesson, LessonSheet::Pupil));
        const std::string teacher = pageText(lessonSheetHtml(lesson, LessonSheet::Teacher));
        ASSERT_FALSE(lesson.teacherNotes.empty()) << "a shipped lesson has teacher's notes with the answers";
        int answers = 0;
        for (const MarkdownBlock& b : parseMarkdownBlocks(lesson.teacherNotes)) {
            const std::string answer = squeeze(b.plainText());
            if (answer.empty()) continue;
            ++answers;
            EXPECT_EQ(pupil.find(answer), std::string::npos) << "the worksheet shows the answer: " << answer;
            EXPECT_NE(teacher.find(answer), std::string::npos) << "the teacher's sheet lacks: " << answer;
        }
        EXPECT_GT(answers, 0);
        EXPECT_EQ(pupil.find("Teacher's notes"), std::string::npos);
        EXPECT_EQ(pupil.find("Minutes:"), std::string::npos);
        EXPECT_NE(teacher.find("Level: " + lesson.level), std::string::npos);
        EXPECT_NE(teacher.find("Minutes: " + std::to_string(lesson.minutes)), std::string::npos);
        for (const LessonStep& s : lesson.steps) {
            const std::string title = squeeze(s.title);
            EXPECT_NE(pupil.find(title), std::string::npos) << title;
            EXPECT_NE(teacher.find(title + (s.optional ? " optional" : " core")), std::string::npos) << title;
            EXPECT_NE(teacher.find(s.commands.front().name + " " + s.commands.front().args.front()), std::string::npos)
                << "the teacher's sheet shows the step's script";
        }
        for (const std::string& q : lesson.questions) {
            const std::string question = squeeze(parseMarkdownBlocks(q).front().plainText());
            EXPECT_NE(pupil.find(question), std::string::npos) << question;
        }
    }
}

// A Dutch lesson's sheets speak Dutch around its text: the words come from its language.
TEST(LessonSheet, ADutchLessonsSheetsAreInDutchAndThePupilsHasNoNotes) {
    const fs::path dir = fs::temp_directory_path() / ("raylab_sheet_dutch_" + std::to_string(::getpid()));
    const test::DutchLessonFixture f = test::makeDutchLessonFixture(dir, "07-lambert.md");
    const Lesson nl = loadLesson(f.dutch);
    const std::string pupilHtml = lessonSheetHtml(nl, LessonSheet::Pupil), teacherHtml = lessonSheetHtml(nl, LessonSheet::Teacher);
    EXPECT_NE(pupilHtml.find("<html lang=\"nl\">"), std::string::npos);
    const std::string pupil = pageText(pupilHtml), teacher = pageText(teacherHtml);
    EXPECT_NE(pupil.find("Naam: ___"), std::string::npos);
    EXPECT_NE(pupil.find("Leerdoelen"), std::string::npos);
    EXPECT_NE(pupil.find("Stap 6: What Lambert leaves out"), std::string::npos) << pupil;
    EXPECT_EQ(pupil.find("Aantekeningen voor de docent"), std::string::npos);
    EXPECT_EQ(pupil.find("Q3: the bowl sees itself"), std::string::npos) << "an answer on the worksheet";
    EXPECT_EQ(pupil.find("{#"), std::string::npos);
    EXPECT_NE(teacher.find("Docentenblad \u00b7 Niveau: " + nl.level + " \u00b7 Minuten: 45 \u00b7 Stappen: 5 kern, 1 facultatief"),
              std::string::npos)
        << teacher.substr(0, 400);
    EXPECT_NE(teacher.find("Stap 6: What Lambert leaves out facultatief"), std::string::npos);
    EXPECT_NE(teacher.find("Aantekeningen voor de docent en antwoorden"), std::string::npos);
    EXPECT_NE(teacher.find("Q3: the bowl sees itself"), std::string::npos);
    EXPECT_EQ(teacher.find("Teacher's"), std::string::npos) << "no English word of the sheet's own";
    fs::remove_all(dir);
}

TEST(LessonSheet, PicturesAreEmbeddedAsDataUris) {
    for (const Lesson& lesson : loadLessons(kLessons)) {
        SCOPED_TRACE(lesson.file.string());
        const std::string html = lessonSheetHtml(lesson, LessonSheet::Teacher);
        EXPECT_EQ(count(html, "<img src=\"data:image/png;base64,"), lesson.pictures.size());
        EXPECT_EQ(count(html, "<img"), lesson.pictures.size());
        EXPECT_EQ(count(html, "<link") + count(html, "<script"), 0u) << "the page needs no other file";
    }
}

TEST(LessonSheet, AMissingPictureIsALocatedError) {
    const fs::path dir = fs::temp_directory_path() / "raylab_sheet_missing_picture";
    fs::create_directories(dir / "lessons");
    fs::create_directories(dir / "scenes");
    std::ofstream(dir / "scenes/s.json") << "{}";
    const fs::path file = dir / "lessons/01-x.md";
    std::ofstream(file) << "# X\n\nScene: scenes/s.json\n\n## Learning goals {#goals}\n\n- g\n\n## Step 1: S {#step}\n\nText\n\n"
                           "![the slab test](pictures/nowhere.png)\n\n```raylab\nopen scenes/s.json\n```\n\n"
                           "## Questions {#questions}\n\n1. q\n\n## Exercise {#exercise}\n\ne\n";
    const Lesson lesson = loadLesson(file);
    ASSERT_EQ(lesson.pictures.size(), 1u);
    EXPECT_EQ(lesson.pictures[0].line, 13);
    EXPECT_EQ(lesson.pictures[0].source, "pictures/nowhere.png");
    try {
        lessonSheetHtml(lesson, LessonSheet::Pupil);
        ADD_FAILURE() << "a missing picture was not reported";
    } catch (const LessonError& e) {
        EXPECT_NE(std::string(e.what()).find(file.string() + ":13: error: cannot read the picture 'pictures/nowhere.png'"), std::string::npos)
            << e.what();
    }
    fs::remove_all(dir);
}

TEST(MarkdownHtml, WritesCommonMarkBlocksAndSpans) {
    EXPECT_EQ(markdownToHtml("# T\n\nA *b* **c** `d<e` [f](g.html) ~~h~~\n", kNoImages),
              "<h1>T</h1>\n<p>A <em>b</em> <strong>c</strong> <code>d&lt;e</code> <a href=\"g.html\">f</a> <del>h</del></p>\n");
    EXPECT_EQ(markdownToHtml("- a\n- b\n\n3. c\n", kNoImages), "<ul>\n<li>a</li>\n<li>b</li>\n</ul>\n<ol start=\"3\">\n<li>c</li>\n</ol>\n");
    EXPECT_EQ(markdownToHtml("```glsl\nx < y\n```\n", kNoImages), "<pre><code class=\"language-glsl\">x &lt; y\n</code></pre>\n");
    EXPECT_EQ(markdownToHtml("| a | b |\n|---|--:|\n| 1 | 2 |\n", kNoImages),
              "<table>\n<thead>\n<tr><th>a</th><th style=\"text-align:right\">b</th></tr>\n</thead>\n"
              "<tbody>\n<tr><td>1</td><td style=\"text-align:right\">2</td></tr>\n</tbody>\n</table>\n");
    EXPECT_EQ(markdownToHtml("> q &amp; <b>raw</b>\n", kNoImages), "<blockquote>\n<p>q &amp; &lt;b&gt;raw&lt;/b&gt;</p>\n</blockquote>\n")
        << "raw HTML is text, as in the viewer";
}

TEST(MarkdownHtml, HeadingsLoseTheirRoleMarker) {
    EXPECT_EQ(markdownToHtml("## Leerdoelen {#goals}\n\n## Step 2: `x` {#step .optional}\n\n## A {b}\n", kNoImages),
              "<h2>Leerdoelen</h2>\n<h2>Step 2: <code>x</code></h2>\n<h2>A {b}</h2>\n");
}

TEST(MarkdownHtml, AnImageTakesItsSourceFromTheCallerAndItsAltTextWithoutTags) {
    EXPECT_EQ(markdownToHtml("![the *slab* test](p/slab.png)\n", kNoImages),
              "<p><img src=\"IMG(p/slab.png)\" alt=\"the slab test\"></p>\n");
    const ImageSource failing = [](const std::string& src) -> std::string { throw LessonError("no " + src); };
    EXPECT_THROW(markdownToHtml("![a](b.png)\n", failing), LessonError);
}

TEST(DataUri, Base64FollowsRfc4648) {
    const std::pair<std::string, std::string> vectors[] = {   // RFC 4648 §10, and bytes above 127
        {"", ""}, {"f", "Zg=="}, {"fo", "Zm8="}, {"foo", "Zm9v"}, {"foobar", "Zm9vYmFy"}, {std::string("\xff\x00\x80", 3), "/wCA"}};
    for (const auto& [bytes, text] : vectors) EXPECT_EQ(base64(bytes), text);
}
