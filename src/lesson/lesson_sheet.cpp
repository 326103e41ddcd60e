#include "lesson/lesson_sheet.h"

#include "lesson/data_uri.h"
#include "lesson/lesson_words.h"
#include "lesson/markdown_html.h"

#include <algorithm>

namespace raylab {
namespace {

// Screen and print: A4 pages, pictures at most the text's width, headings kept with what follows.
constexpr const char* kCss = R"(body { font-family: "DejaVu Serif", Georgia, serif; font-size: 11pt; line-height: 1.45;
  max-width: 46em; margin: 2em auto; padding: 0 1em; color: #111; }
h1 { font-size: 1.7em; margin-bottom: 0.2em; }
h2 { font-size: 1.25em; border-bottom: 1px solid #999; margin-top: 1.6em; }
h1, h2, h3 { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; break-after: avoid; page-break-after: avoid; }
.meta { color: #444; font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; font-size: 0.95em; }
.mark { font-size: 0.7em; font-weight: normal; border: 1px solid #777; border-radius: 3px; padding: 0 0.3em; margin-left: 0.5em; }
pre { background: #f3f3f3; padding: 0.5em 0.8em; overflow-x: auto; font-size: 0.9em; white-space: pre-wrap; }
code { font-family: "DejaVu Sans Mono", monospace; font-size: 0.92em; }
pre.script { background: #eef3fa; border-left: 3px solid #6b8fc7; }
img { max-width: 100%; height: auto; display: block; margin: 0.6em auto; break-inside: avoid; page-break-inside: avoid; }
table { border-collapse: collapse; margin: 0.6em 0; }
th, td { border: 1px solid #999; padding: 0.2em 0.5em; }
blockquote { border-left: 3px solid #bbb; margin-left: 0; padding-left: 1em; color: #333; }
.answer { height: 5.5em; border-bottom: 1px dotted #777; margin-bottom: 0.8em; }
.exercise-space { height: 14em; border: 1px dotted #777; }
.teacher { border: 1px solid #c59a3c; background: #fdf7e8; padding: 0 1em; }
@page { size: A4; margin: 16mm; }
@media print { body { margin: 0; max-width: none; } a { color: inherit; text-decoration: none; }
  pre, table, blockquote, li { break-inside: avoid; page-break-inside: avoid; } }
)";

// Markdown of one list item or line, without the paragraph md4c wraps it in.
std::string inlineHtml(const std::string& markdown, const ImageSource& images) {
    std::string html = markdownToHtml(markdown, images);
    if (html.rfind("<p>", 0) == 0 && html.size() >= 8 && html.compare(html.size() - 5, 5, "</p>\n") == 0)
        html = html.substr(3, html.size() - 8);
    return html;
}

std::string section(const std::string& cls, const std::string& heading, const std::string& body) {
    return "<section class=\"" + cls + "\">\n<h2>" + htmlEscape(heading) + "</h2>\n" + body + "</section>\n";
}

std::string scriptText(const LessonStep& step) {
    std::string s;
    for (const ScriptCommand& c : step.commands) {
        s += c.name;
        for (const std::string& a : c.args) s += " " + a;
        s += "\n";
    }
    return s;
}

} // namespace

std::string lessonSheetHtml(const Lesson& lesson, LessonSheet sheet) {
    const bool teacher = sheet == LessonSheet::Teacher;
    const ImageSource images = [&](const std::string& source) {
        const std::filesystem::path file = lesson.picturePath(source);
        if (auto uri = fileDataUri(file)) return *uri;
        const auto it = std::find_if(lesson.pictures.begin(), lesson.pictures.end(),
                                     [&](const LessonPicture& p) { return p.source == source; });
        const std::string where = lesson.file.string() + (it != lesson.pictures.end() && it->line > 0 ? ":" + std::to_string(it->line) : "");
        throw LessonError(where + ": error: cannot read the picture '" + source + "' (" + file.string() + ")");
    };
    auto md = [&](const std::string& markdown) { return markdownToHtml(markdown, images); };

    const LessonWords& w = lessonWords(lesson.language);
    const std::string sep = " \u00b7 ";
    std::string h = "<!DOCTYPE html>\n<html lang=\"" + htmlEscape(lesson.language) + "\">\n<head>\n<meta charset=\"utf-8\">\n<title>" +
                    htmlEscape(lesson.title) + " \u2014 " + (teacher ? w.teacherSheet : w.worksheet) + "</title>\n<style>\n" + kCss +
                    "</style>\n</head>\n<body class=\"" + (teacher ? "teacher-sheet" : "pupil-sheet") + "\">\n<header>\n<h1>" +
                    htmlEscape(lesson.title) + "</h1>\n";
    if (teacher) {
        int core = 0;
        for (const LessonStep& s : lesson.steps) core += s.optional ? 0 : 1;
        h += "<p class=\"meta\">" + std::string(w.teacherSheetHeading) + sep + w.level + ": " +
             htmlEscape(lesson.level.empty() ? w.notGiven : lesson.level) + sep + w.minutesLabel + ": " +
             (lesson.minutes > 0 ? std::to_string(lesson.minutes) : w.notGiven) + sep + w.steps + ": " + std::to_string(core) + " " +
             w.core + ", " + std::to_string(int(lesson.steps.size()) - core) + " " + w.optional + sep + w.scene + ": <code>" +
             htmlEscape(lesson.scene) + "</code></p>\n";
    } else {
        h += "<p class=\"meta\">" + std::string(w.name) + ": ______________________ \u00a0 " + w.className +
             ": ________ \u00a0 " + w.date + ": ____________</p>\n";
    }
    h += "</header>\n";
    if (!lesson.introduction.empty()) h += "<section class=\"introduction\">\n" + md(lesson.introduction) + "</section>\n";

    std::string goals = "<ul>\n";
    for (const std::string& g : lesson.goals) goals += "<li>" + inlineHtml(g, images) + "</li>\n";
    h += section("goals", lesson.heading(LessonRole::Goals), goals + "</ul>\n");

    for (const LessonStep& s : lesson.steps) {
        h += "<section class=\"step\">\n<h2>" + htmlEscape(s.heading);
        if (teacher) h += std::string(" <span class=\"mark\">") + (s.optional ? w.optional : w.core) + "</span>";
        h += "</h2>\n" + md(s.text);
        if (teacher) {
            const int parts = s.partCount();
            h += "<p class=\"meta\">" + std::string(w.inRaylab) +
                 (parts > 1 ? " (" + std::to_string(parts) + " " + w.subSteps + ")" : std::string()) +
                 ":</p>\n<pre class=\"script\"><code>" + htmlEscape(scriptText(s)) + "</code></pre>\n";
        }
        h += "</section>\n";
    }

    std::string questions = "<ol class=\"questions\">\n";
    for (const std::string& q : lesson.questions)
        questions += "<li>" + inlineHtml(q, images) + (teacher ? "" : "\n<div class=\"answer\"></div>") + "</li>\n";
    h += section("questions", lesson.heading(LessonRole::Questions), questions + "</ol>\n");
    h += section("exercise", lesson.heading(LessonRole::Exercise),
                 md(lesson.exercise) + (teacher ? "" : "<div class=\"exercise-space\"></div>\n"));
    if (!lesson.writeItYourself.empty()) h += section("write-it-yourself", lesson.heading(LessonRole::Code), md(lesson.writeItYourself));
    if (!lesson.goingFurther.empty()) h += section("going-further", lesson.heading(LessonRole::Further), md(lesson.goingFurther));
    if (teacher && !lesson.teacherNotes.empty())
        h += "<section class=\"teacher\">\n<h2>" + htmlEscape(w.notesAndAnswers) + "</h2>\n" + md(lesson.teacherNotes) + "</section>\n";
    if (!lesson.sources.empty()) h += section("sources", lesson.heading(LessonRole::Sources), md(lesson.sources));
    return h + "</body>\n</html>\n";
}

} // namespace raylab
