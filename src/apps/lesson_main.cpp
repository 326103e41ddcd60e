// raylab-lesson: lessons off the screen. `list` prints the lessons; `export LESSON --pupil|--teacher
// -o FILE.html` writes a printable, self-contained handout: the pupil's worksheet (no answers) or
// the teacher's sheet (level, minutes, core and optional steps, scripts, answers and notes).
// LESSON is a lesson file, or a lesson's name in the lessons folder ("03-ray-sphere" or "03");
// `--lang nl` takes the Dutch edition (lessons/nl/) instead.
// Exit status: 0 done, 1 bad input (lesson, picture, output), 2 bad command line.
#include "lesson/lesson.h"
#include "lesson/lesson_edition.h"
#include "lesson/lesson_sheet.h"
#include "lesson/lesson_words.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include <filesystem>
#include <fstream>
#include <iostream>

namespace fs = std::filesystem;

namespace {

// The shipped lessons of `language`'s edition: beside the shader folder, as the exercises are.
fs::path lessonDirectory(const std::string& language) {
    return raylab::lessonEditionFolder(fs::path(RAYLAB_SOURCE_SHADER_DIR).parent_path() / "lessons", language);
}

std::vector<fs::path> lessonFiles(const std::string& language) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(lessonDirectory(language), ec))
        if (e.path().extension() == ".md" && e.path().filename() != "README.md") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

// A file as given (its edition in `language` when --lang was given), else the lesson of `language`
// whose name is NAME or starts with "NAME-".
fs::path findLesson(const std::string& name, const std::string& language, bool languageGiven) {
    std::error_code ec;
    if (fs::is_regular_file(name, ec)) {
        const auto edition = languageGiven ? raylab::lessonInLanguage(name, language) : std::nullopt;
        return edition ? *edition : fs::path(name);
    }
    std::string known;
    for (const fs::path& f : lessonFiles(language)) {
        const std::string stem = f.stem().string();
        if (stem == name || stem.rfind(name + "-", 0) == 0) return f;
        known += (known.empty() ? "" : ", ") + stem;
    }
    throw raylab::LessonError(name + ": error: no such lesson file, nor a lesson of that name in " +
                              lessonDirectory(language).string() + " (" + known + ")");
}

int list(const std::string& language) {
    std::cout << "name\tlevel\tminutes\ttitle\n";
    for (const fs::path& f : lessonFiles(language)) {
        const raylab::Lesson l = raylab::loadLesson(f);
        std::cout << f.stem().string() << "\t" << l.level << "\t" << l.minutes << "\t" << l.title << "\n";
    }
    return 0;
}

int exportSheet(const std::string& name, const std::string& language, bool languageGiven, bool teacher, const std::string& output) {
    const raylab::Lesson lesson = raylab::loadLesson(findLesson(name, language, languageGiven));
    const std::string html = raylab::lessonSheetHtml(lesson, teacher ? raylab::LessonSheet::Teacher : raylab::LessonSheet::Pupil);
    std::ofstream out(output, std::ios::binary);
    if (!out || !(out << html) || !out.flush()) {
        std::cerr << output << ": error: cannot write the sheet (" << std::strerror(errno) << ")\n";
        return 1;
    }
    std::cout << output << "\n";
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    CLI::App app{"raylab-lesson: the lessons as printable handouts"};
    app.require_subcommand(1);
    std::string language = raylab::kDefaultLessonLanguage;
    const std::string langHelp = "The lessons' language: " + raylab::lessonLanguageList() + " (nl: the Dutch edition, lessons/nl/)";
    app.add_subcommand("list", "Print the lessons: name, level, minutes, title")->add_option("--lang", language, langHelp);
    CLI::App* exportCmd = app.add_subcommand("export", "Write a lesson's worksheet (--pupil) or teacher's sheet (--teacher) as HTML");
    std::string lesson, output;
    bool pupil = false, teacher = false;
    exportCmd->add_option("lesson", lesson, "A lesson file, or a lesson's name (03-ray-sphere, 03)")->required();
    exportCmd->add_flag("--pupil", pupil, "The pupil's worksheet: no answers, no teacher's notes");
    exportCmd->add_flag("--teacher", teacher, "The teacher's sheet: level, minutes, steps' marks and scripts, answers, notes");
    exportCmd->add_option("-o,--output", output, "The HTML file to write (.html)")->required();
    const CLI::Option* exportLang = exportCmd->add_option("--lang", language, langHelp);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : 2;
    }
    if (!raylab::isLessonLanguage(language)) {
        std::cerr << "raylab-lesson: error: --lang: unknown language '" << language << "' (" << raylab::lessonLanguageList() << ")\n";
        return 2;
    }
    if (app.got_subcommand("export")) {
        if (pupil == teacher) {
            std::cerr << "raylab-lesson export: error: give one of --pupil or --teacher\n";
            return 2;
        }
        const fs::path ext = fs::path(output).extension();
        if (ext != ".html" && ext != ".htm") {
            std::cerr << output << ": error: the sheet is HTML: name the output FILE.html\n";
            return 2;
        }
    }
    try {
        if (app.got_subcommand("list")) return list(language);
        return exportSheet(lesson, language, exportLang->count() > 0, teacher, output);
    } catch (const std::exception& e) {
        std::cerr << e.what() << "\n";
        return 1;
    }
}
