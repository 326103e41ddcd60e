#include "lesson/lesson.h"

#include "lesson/lesson_words.h"
#include "lesson/markdown_dialect.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <optional>
#include <regex>
#include <sstream>

namespace raylab {
namespace {

// A fenced code block found by scanning lines. md4c (like CommonMark) lets an unclosed fence run
// to the end of the file silently; lessons call that an error, so fences are also found here.
struct Fence {
    int open = 0;    // 1-based line of the opening fence
    int close = 0;   // 1-based line of the closing fence
};

// A block of interest reported by md4c, with the line of its first text.
struct Block {
    enum Kind { Heading, Code, Paragraph, Item };
    explicit Block(Kind k, int lvl = 0) : kind(k), level(lvl) {}
    Kind kind;
    int level = 0;       // heading level, or list nesting of an item
    int line = 0;        // 0 while no text has located it
    bool fenced = false;
    std::string info;    // code: the info string
    std::string text;    // Markdown-ish text (inline code and emphasis kept as markers)
    std::string plain;   // text up to the first line break, without markers
    bool plainDone = false;
};

struct Collector {
    const char* begin = nullptr;
    const char* end = nullptr;
    std::vector<size_t> lineStarts;
    std::vector<Block> blocks;
    int listDepth = 0;          // nesting of ul/ol
    int itemDepth = 0;          // nesting of li
    int quoteDepth = 0;
    std::optional<size_t> sink; // the block that text goes to
    std::optional<size_t> item; // the open top-level list item
    std::vector<std::pair<LessonPicture, std::optional<size_t>>> pictures;   // with the block that locates a source md4c copied

    int lineOf(const char* p) const {
        if (p < begin || p >= end) return 0;
        const auto off = size_t(p - begin);
        return int(std::upper_bound(lineStarts.begin(), lineStarts.end(), off) - lineStarts.begin());
    }
    void open(Block b) {
        blocks.push_back(std::move(b));
        sink = blocks.size() - 1;
    }
    void append(std::string_view markers) {
        if (sink) blocks[*sink].text += markers;
    }
};

int enterBlock(MD_BLOCKTYPE type, void* detail, void* user) {
    auto& c = *static_cast<Collector*>(user);
    switch (type) {
    case MD_BLOCK_H:
        c.open(Block(Block::Heading, int(static_cast<MD_BLOCK_H_DETAIL*>(detail)->level)));
        break;
    case MD_BLOCK_CODE: {
        const auto* d = static_cast<MD_BLOCK_CODE_DETAIL*>(detail);
        Block b(Block::Code);
        b.fenced = d->fence_char != 0;
        b.info.assign(d->info.text, d->info.size);
        c.open(std::move(b));
        break;
    }
    case MD_BLOCK_UL:
    case MD_BLOCK_OL: ++c.listDepth; break;
    case MD_BLOCK_LI:
        if (++c.itemDepth == 1 && c.quoteDepth == 0) {
            c.open(Block(Block::Item, c.listDepth));
            c.item = c.sink;
        }
        break;
    case MD_BLOCK_QUOTE: ++c.quoteDepth; break;
    case MD_BLOCK_P:
        if (c.itemDepth == 0 && c.quoteDepth == 0) c.open(Block(Block::Paragraph));
        else if (c.sink && !c.blocks[*c.sink].text.empty()) c.append(" ");
        break;
    default: break;
    }
    return 0;
}

int leaveBlock(MD_BLOCKTYPE type, void*, void* user) {
    auto& c = *static_cast<Collector*>(user);
    switch (type) {
    case MD_BLOCK_H:
    case MD_BLOCK_CODE: c.sink = c.item; break;   // text after a code block in an item is the item's
    case MD_BLOCK_UL:
    case MD_BLOCK_OL: --c.listDepth; break;
    case MD_BLOCK_LI:
        if (--c.itemDepth == 0) c.sink = c.item = std::nullopt;
        break;
    case MD_BLOCK_QUOTE: --c.quoteDepth; break;
    case MD_BLOCK_P:
        if (c.itemDepth == 0 && c.quoteDepth == 0) c.sink.reset();
        break;
    default: break;
    }
    return 0;
}

std::string_view spanMarker(MD_SPANTYPE type) {
    switch (type) {
    case MD_SPAN_CODE: return "`";
    case MD_SPAN_EM: return "*";
    case MD_SPAN_STRONG: return "**";
    default: return "";
    }
}

int enterSpan(MD_SPANTYPE type, void* detail, void* user) {
    auto& c = *static_cast<Collector*>(user);
    if (type == MD_SPAN_IMG) {
        const MD_ATTRIBUTE& src = static_cast<MD_SPAN_IMG_DETAIL*>(detail)->src;
        c.pictures.push_back({{c.lineOf(src.text), std::string(src.text, src.size)}, c.sink});
    }
    c.append(spanMarker(type));
    return 0;
}

int leaveSpan(MD_SPANTYPE type, void*, void* user) {
    static_cast<Collector*>(user)->append(spanMarker(type));
    return 0;
}

int onText(MD_TEXTTYPE type, const MD_CHAR* text, MD_SIZE size, void* user) {
    auto& c = *static_cast<Collector*>(user);
    if (!c.sink) return 0;
    Block& b = c.blocks[*c.sink];
    if (b.line == 0) b.line = c.lineOf(text);
    switch (type) {
    case MD_TEXT_NULLCHAR: return 0;
    case MD_TEXT_BR:
    case MD_TEXT_SOFTBR:
        b.text += ' ';
        b.plainDone = true;
        return 0;
    default:
        b.text.append(text, size);
        if (!b.plainDone) b.plain.append(text, size);
        return 0;
    }
}

std::string trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    return std::string(s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1));
}

std::vector<std::string> splitLines(std::string_view text) {
    std::vector<std::string> lines;
    size_t start = 0;
    while (start <= text.size()) {
        size_t nl = text.find('\n', start);
        if (nl == std::string_view::npos) nl = text.size();
        std::string line(text.substr(start, nl - start));
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(std::move(line));
        start = nl + 1;
    }
    return lines;
}

// CommonMark fences: three or more ` or ~; a backtick fence's info string has no backtick; the
// closing fence uses the same character, is at least as long, and has nothing after it.
std::vector<Fence> scanFences(const std::vector<std::string>& lines, const std::string& file) {
    std::vector<Fence> fences;
    char ch = 0;
    size_t len = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::string& l = lines[i];
        const size_t indent = l.find_first_not_of(" \t");
        if (indent == std::string::npos) continue;
        const char first = l[indent];
        if (first != '`' && first != '~') continue;
        const size_t run = l.find_first_not_of(first, indent) == std::string::npos
                               ? l.size() - indent
                               : l.find_first_not_of(first, indent) - indent;
        if (run < 3) continue;
        const std::string rest = trim(std::string_view(l).substr(indent + run));
        if (ch == 0) {
            if (first == '`' && rest.find('`') != std::string::npos) continue;   // inline code
            ch = first;
            len = run;
            fences.push_back({int(i + 1), 0});
        } else if (first == ch && run >= len && rest.empty()) {
            fences.back().close = int(i + 1);
            ch = 0;
        }
    }
    if (ch != 0)
        throw LessonError(file + ":" + std::to_string(fences.back().open) +
                          ": error: unclosed code fence (it runs to the end of the file)");
    return fences;
}

enum class Section { BeforeTitle, Introduction, Role };

// The code-track exercises a "Write it yourself" section opens: every `--exercise NAME` in it.
std::vector<std::string> codeExercisesIn(const std::string& text) {
    static const std::regex option(R"(--exercise\s+([a-z0-9-]+))");
    std::vector<std::string> names;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), option); it != std::sregex_iterator(); ++it)
        if (std::find(names.begin(), names.end(), (*it)[1].str()) == names.end()) names.push_back((*it)[1].str());
    return names;
}

// Step numbers are checked to count 1, 2, 3...; one read as more than this is out of order anyway,
// so reading stops growing it there (no overflow).
constexpr int kMaxStepNumber = 9999;

// "WORD N: TITLE" (also "WORD N. TITLE"; WORD is "Step", "Stap"); nullopt when it is not that.
std::optional<std::pair<int, std::string>> parseStepHeading(const std::string& heading) {
    const size_t space = heading.find(' ');
    if (space == 0 || space == std::string::npos) return std::nullopt;
    size_t i = space + 1;
    int n = 0;
    bool digits = false;
    while (i < heading.size() && std::isdigit(static_cast<unsigned char>(heading[i]))) {
        n = std::min(n * 10 + (heading[i++] - '0'), kMaxStepNumber + 1);   // past the limit: out of order
        digits = true;
    }
    if (!digits || i >= heading.size() || (heading[i] != ':' && heading[i] != '.')) return std::nullopt;
    return std::pair{n, trim(std::string_view(heading).substr(i + 1))};
}

// A paragraph "KEY: value" of the introduction (Scene, Level, Minutes, Language); nullopt for any other.
std::optional<std::pair<std::string, std::string>> frontMatter(const std::string& plain) {
    for (const char* key : {"Scene:", "Level:", "Minutes:", "Language:"})
        if (plain.rfind(key, 0) == 0) return std::pair{std::string(key), trim(std::string_view(plain).substr(std::strlen(key)))};
    return std::nullopt;
}

} // namespace

int LessonStep::partCount() const {
    return 1 + int(std::count_if(commands.begin(), commands.end(), [](const ScriptCommand& c) { return c.name == "hold"; }));
}

std::vector<ScriptCommand> LessonStep::partScript(int part) const {
    std::vector<ScriptCommand> script;
    int current = 0;
    for (const ScriptCommand& c : commands) {
        if (c.name == "hold") {
            if (++current > part) break;
            continue;
        }
        const bool wait = c.name == "wait-spp" || c.name == "wait-frames";
        if (current == part || !wait) script.push_back(c);
    }
    return script;
}

std::filesystem::path Lesson::resolve(const std::string& path) const {
    return (root / path).lexically_normal();
}

std::filesystem::path Lesson::picturePath(const std::string& source) const {
    return (file.parent_path() / source).lexically_normal();
}

std::string Lesson::heading(LessonRole role) const {
    const auto it = std::find_if(sections.begin(), sections.end(), [&](const LessonSection& s) { return s.role == role; });
    if (it != sections.end()) return it->heading;
    const LessonWords& w = lessonWords(language);
    switch (role) {
    case LessonRole::Goals: return w.goals;
    case LessonRole::Step: return w.step;
    case LessonRole::Questions: return w.questions;
    case LessonRole::Exercise: return w.exercise;
    case LessonRole::Code: return w.code;
    case LessonRole::Further: return w.further;
    case LessonRole::Notes: return w.notes;
    case LessonRole::Sources: return w.sources;
    }
    return {};
}

Lesson parseLesson(std::string_view text, const std::filesystem::path& file, const std::filesystem::path& root) {
    const std::string name = file.string();
    auto fail = [&](int line, const std::string& what) -> LessonError {
        return LessonError(line > 0 ? name + ":" + std::to_string(line) + ": error: " + what
                                    : name + ": error: " + what);
    };
    const std::vector<std::string> lines = splitLines(text);
    const std::vector<Fence> fences = scanFences(lines, name);

    Collector c;
    c.begin = text.data();
    c.end = text.data() + text.size();
    c.lineStarts.push_back(0);
    for (size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') c.lineStarts.push_back(i + 1);
    const MD_PARSER parser = lessonMarkdownParser(enterBlock, leaveBlock, enterSpan, leaveSpan, onText);
    if (md_parse(text.data(), MD_SIZE(text.size()), &parser, &c) != 0) throw fail(0, "md4c could not parse the file");

    Lesson lesson;
    lesson.file = file;
    lesson.root = root;
    int titleLine = 0;
    Section section = Section::BeforeTitle;
    LessonRole role = LessonRole::Goals;   // the current section's, when section is Role
    int sectionLine = 0;       // heading line of the current section (or the title's)
    int goalsLine = 0, questionsLine = 0, exerciseLine = 0, languageLine = 0;
    std::vector<std::pair<int, int>> hidden;   // line ranges left out of Markdown slices (1-based)
    size_t fenceIndex = 0;

    // The Markdown of lines (from, to], without hidden ranges, trimmed of blank lines at both ends.
    auto slice = [&](int from, int to) {
        auto isHidden = [&](int l) {
            return std::any_of(hidden.begin(), hidden.end(), [&](const auto& r) { return l >= r.first && l <= r.second; });
        };
        std::string out;
        bool lastBlank = true;
        for (int l = from + 1; l <= to && l <= int(lines.size()); ++l) {
            if (isHidden(l)) continue;
            const bool blank = trim(lines[size_t(l - 1)]).empty();
            // A removed block leaves blank lines on both sides: keep one.
            if (blank && lastBlank && isHidden(l - 1)) continue;
            out += lines[size_t(l - 1)] + "\n";
            lastBlank = blank;
        }
        const auto first = out.find_first_not_of(" \t\n");
        if (first == std::string::npos) return std::string();
        // Keep a first line's indentation: drop whole blank lines only.
        const auto lineStart = out.rfind('\n', first);
        out.erase(0, lineStart == std::string::npos ? 0 : lineStart + 1);
        out.erase(out.find_last_not_of(" \t\n") + 1);
        return out;
    };
    // Called when a section ends just before line `next` (a heading line, or past the end).
    auto closeSection = [&](int next) {
        const int last = next - 1;
        if (section == Section::Introduction) lesson.introduction = slice(titleLine, last);
        if (section != Section::Role) return;
        switch (role) {
        case LessonRole::Step: lesson.steps.back().text = slice(sectionLine, last); break;
        case LessonRole::Exercise: lesson.exercise = slice(sectionLine, last); break;
        case LessonRole::Code:
            lesson.writeItYourself = slice(sectionLine, last);
            lesson.codeExercises = codeExercisesIn(lesson.writeItYourself);
            break;
        case LessonRole::Further: lesson.goingFurther = slice(sectionLine, last); break;
        case LessonRole::Notes: lesson.teacherNotes = slice(sectionLine, last); break;
        case LessonRole::Sources: lesson.sources = slice(sectionLine, last); break;
        default: break;
        }
    };
    auto inRole = [&](LessonRole r) { return section == Section::Role && role == r; };

    int lastLine = 1;   // the latest located line, for blocks md4c gave no text for
    for (Block& b : c.blocks) {
        if (b.line == 0) b.line = lastLine;
        lastLine = b.line;
        switch (b.kind) {
        case Block::Heading: {
            if (b.level > 2) break;
            const std::string heading = trim(b.text);
            // Sections are cut at heading lines; an underlined (setext) heading spans two.
            if (!heading.empty() && trim(lines[size_t(b.line - 1)]).rfind('#', 0) != 0)
                throw fail(b.line, "write headings as '# ' and '## ', not underlined");
            if (b.level == 1) {
                if (section != Section::BeforeTitle)
                    throw fail(b.line, "a second '# ' title; a lesson has one, sections are '## '");
                if (withoutSectionMarker(heading) != heading)
                    throw fail(b.line, "the '# ' title takes no marker; '## ' sections do");
                lesson.title = heading;
                titleLine = sectionLine = b.line;
                section = Section::Introduction;
                break;
            }
            if (section == Section::BeforeTitle) throw fail(b.line, "the lesson must start with a '# TITLE' heading");
            const auto parsed = parseMarkedHeading(heading);
            if (const auto* error = std::get_if<std::string>(&parsed)) throw fail(b.line, *error);
            const MarkedHeading& marked = std::get<MarkedHeading>(parsed);
            closeSection(b.line);
            sectionLine = b.line;
            section = Section::Role;
            role = marked.role;
            if (role != LessonRole::Step)
                for (const LessonSection& earlier : lesson.sections)
                    if (earlier.role == role)
                        throw fail(b.line, "a second " + roleMarker(role) + " section (the first is on line " +
                                               std::to_string(earlier.line) + ")");
            lesson.sections.push_back({role, b.line, marked.text});
            if (role == LessonRole::Goals) goalsLine = b.line;
            if (role == LessonRole::Questions) questionsLine = b.line;
            if (role == LessonRole::Exercise) exerciseLine = b.line;
            if (role != LessonRole::Step) break;
            const auto step = parseStepHeading(marked.text);
            const int expected = int(lesson.steps.size()) + 1;
            if (!step)
                throw fail(b.line, "a step heading is 'WORD N: TITLE' (Step " + std::to_string(expected) + ": ..., Stap " +
                                       std::to_string(expected) + ": ...), not '" + marked.text + "'");
            if (step->first != expected)
                throw fail(b.line, "step numbered " +
                                       (step->first > kMaxStepNumber ? "above " + std::to_string(kMaxStepNumber)
                                                                     : std::to_string(step->first)) +
                                       ", expected " + std::to_string(expected));
            if (step->second.empty()) throw fail(b.line, "step " + std::to_string(expected) + " has no title");
            lesson.steps.push_back({b.line, marked.text, step->second, marked.optional, {}, {}});
            break;
        }
        case Block::Paragraph: {
            const auto front = section == Section::Introduction ? frontMatter(trim(b.plain)) : std::nullopt;
            if (!front) break;
            const auto& [key, value] = *front;
            if (b.plainDone) throw fail(b.line, "'" + key + " ...' must be a paragraph of its own");
            if (key == "Scene:") {
                if (!lesson.scene.empty()) throw fail(b.line, "a second 'Scene:' line");
                lesson.scene = value;
                lesson.sceneLine = b.line;
                if (lesson.scene.empty()) throw fail(b.line, "'Scene:' needs a path (relative to the repository root)");
            } else if (key == "Level:") {
                if (!lesson.level.empty()) throw fail(b.line, "a second 'Level:' line");
                if (std::find(std::begin(kLessonLevels), std::end(kLessonLevels), value) == std::end(kLessonLevels))
                    throw fail(b.line, "'Level:' is '" + std::string(kLessonLevels[0]) + "' or '" + kLessonLevels[1] + "'");
                lesson.level = value;
            } else if (key == "Language:") {
                if (languageLine > 0) throw fail(b.line, "a second 'Language:' line");
                if (!isLessonLanguage(value)) throw fail(b.line, "'Language:' is one of " + lessonLanguageList());
                lesson.language = value;
                languageLine = b.line;
            } else {
                if (lesson.minutes > 0) throw fail(b.line, "a second 'Minutes:' line");
                const bool digits = !value.empty() && value.size() < 4 &&
                                    std::all_of(value.begin(), value.end(), [](char ch) { return std::isdigit(static_cast<unsigned char>(ch)); });
                lesson.minutes = digits ? std::stoi(value) : 0;
                if (lesson.minutes <= 0) throw fail(b.line, "'Minutes:' needs the class time in whole minutes");
            }
            hidden.push_back({b.line, b.line});
            break;
        }
        case Block::Item:
            if (b.level != 1) break;
            if (inRole(LessonRole::Goals)) lesson.goals.push_back(trim(b.text));
            if (inRole(LessonRole::Questions)) lesson.questions.push_back(trim(b.text));
            break;
        case Block::Code: {
            if (!b.fenced) break;
            if (fenceIndex >= fences.size()) throw fail(b.line, "cannot locate this code fence");
            const Fence f = fences[fenceIndex++];
            // md4c and the line scan must agree on where the block is (its text starts after the fence).
            if (!b.text.empty() && b.line != f.open + 1)
                throw fail(b.line, "cannot locate this code fence (write fences at the start of a line)");
            b.line = f.open;
            lastLine = f.close;
            const std::string info = trim(b.info);
            if (info != "raylab" && info.rfind("raylab ", 0) != 0) break;
            if (!inRole(LessonRole::Step)) throw fail(f.open, "a ```raylab block outside a {#step} section");
            LessonStep& step = lesson.steps.back();
            if (!step.commands.empty() || std::any_of(hidden.begin(), hidden.end(), [&](const auto& r) {
                    return r.first > step.line;
                }))
                throw fail(f.open, "a second ```raylab block in step " + std::to_string(lesson.steps.size()) +
                                       " (one per step)");
            try {
                step.commands = parseScript(b.text, name, f.open + 1);
            } catch (const ScriptError& e) {
                throw LessonError(e.what());
            }
            if (step.commands.empty())
                throw fail(f.open, "step " + std::to_string(lesson.steps.size()) + ": empty ```raylab block");
            for (size_t i = 0; i < step.commands.size(); ++i)
                if (step.commands[i].name == "hold" &&
                    (i == 0 || i + 1 == step.commands.size() || step.commands[i + 1].name == "hold"))
                    throw fail(step.commands[i].line, std::string("hold with no commands ") +
                                                          (i == 0 ? "before" : "after") + " it (it separates sub-steps)");
            hidden.push_back({f.open, f.close});
            break;
        }
        }
    }
    closeSection(int(lines.size()) + 1);
    for (auto& [picture, block] : c.pictures) {
        if (picture.line == 0 && block) picture.line = c.blocks[*block].line;
        lesson.pictures.push_back(std::move(picture));
    }

    if (section == Section::BeforeTitle) throw fail(1, "no '# TITLE' heading");
    if (lesson.scene.empty()) throw fail(titleLine, "no 'Scene: PATH' line under the title");
    lesson.scenePath = lesson.resolve(lesson.scene);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(lesson.scenePath, ec))
        throw fail(lesson.sceneLine, "scene '" + lesson.scene + "' not found (" + lesson.scenePath.string() + ")");
    if (lesson.goals.empty())
        throw fail(goalsLine ? goalsLine : titleLine, "no learning goals (a {#goals} section's list)");
    if (lesson.steps.empty()) throw fail(titleLine, "no steps ('## Step 1: TITLE {#step}' sections)");
    for (size_t i = 0; i < lesson.steps.size(); ++i)
        if (lesson.steps[i].commands.empty())
            throw fail(lesson.steps[i].line, "step " + std::to_string(i + 1) + " has no ```raylab block");
    if (lesson.questions.empty())
        throw fail(questionsLine ? questionsLine : titleLine, "no questions (a {#questions} section's list)");
    if (lesson.exercise.empty())
        throw fail(exerciseLine ? exerciseLine : titleLine, "no exercise (a {#exercise} section)");
    return lesson;
}

Lesson loadLesson(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw LessonError(file.string() + ": error: cannot read the lesson");
    std::stringstream s;
    s << in.rdbuf();
    return parseLesson(s.str(), file, lessonRoot(file));
}

std::filesystem::path lessonRoot(const std::filesystem::path& file) {
    const std::filesystem::path folder = std::filesystem::absolute(file).lexically_normal().parent_path();
    if (folder.parent_path().filename() == "lessons" && isLessonLanguage(folder.filename().string()))
        return folder.parent_path().parent_path();
    return folder.parent_path();
}

std::vector<Lesson> loadLessons(const std::filesystem::path& dir) {
    std::error_code ec;
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.is_regular_file() && entry.path().extension() == ".md" && entry.path().filename() != "README.md")
            files.push_back(entry.path());
    if (ec) throw LessonError(dir.string() + ": error: cannot list lessons: " + ec.message());
    std::sort(files.begin(), files.end(),
              [](const auto& a, const auto& b) { return a.filename().string() < b.filename().string(); });
    std::vector<Lesson> lessons;
    for (const auto& f : files) lessons.push_back(loadLesson(f));
    return lessons;
}

} // namespace raylab
