#include "lesson/lesson_edition.h"

#include "lesson/lesson_words.h"

#include <algorithm>

namespace raylab {
namespace {

std::string commandText(const ScriptCommand& c) {
    std::string s = c.name;
    for (const std::string& a : c.args) s += " " + a;
    return s;
}

std::string roleNames(const std::vector<LessonSection>& sections) {
    std::string s;
    for (const LessonSection& section : sections) s += (s.empty() ? "" : " ") + roleMarker(section.role);
    return s;
}

// The line of the first section of `role`; the title's (1) when there is none.
int sectionLine(const Lesson& lesson, LessonRole role) {
    for (const LessonSection& s : lesson.sections)
        if (s.role == role) return s.line;
    return 1;
}

} // namespace

std::filesystem::path lessonEditionFolder(const std::filesystem::path& lessons, std::string_view language) {
    return language == kDefaultLessonLanguage ? lessons : lessons / std::string(language);
}

std::optional<std::filesystem::path> lessonInLanguage(const std::filesystem::path& file, std::string_view language) {
    const std::filesystem::path folder = std::filesystem::absolute(file).lexically_normal().parent_path();
    std::filesystem::path lessons;
    if (folder.filename() == "lessons") lessons = folder;
    else if (folder.parent_path().filename() == "lessons" && isLessonLanguage(folder.filename().string())) lessons = folder.parent_path();
    else return std::nullopt;
    return lessonEditionFolder(lessons, language) / file.filename();
}

std::vector<std::string> editionDifferences(const Lesson& original, const Lesson& translation) {
    std::vector<std::string> out;
    const std::string at = translation.file.string() + ":";
    auto differ = [&](int line, const std::string& what) { out.push_back(at + std::to_string(std::max(line, 1)) + ": " + what); };
    auto compare = [&](int line, const std::string& what, const auto& a, const auto& b) {
        if (a != b) differ(line, what + " differs from " + original.file.filename().string() + "'s");
    };
    const int title = 1;
    if (original.language == translation.language) differ(1, "'Language: " + translation.language + "' is the original's language");
    compare(translation.sceneLine, "'Scene: " + translation.scene + "'", translation.scene, original.scene);
    compare(title, "'Level: " + translation.level + "'", translation.level, original.level);
    compare(title, "'Minutes: " + std::to_string(translation.minutes) + "'", translation.minutes, original.minutes);
    compare(title, "the sections (" + roleNames(translation.sections) + ")", roleNames(translation.sections),
            roleNames(original.sections));
    compare(sectionLine(translation, LessonRole::Goals), std::to_string(translation.goals.size()) + " learning goals", translation.goals.size(), original.goals.size());
    compare(sectionLine(translation, LessonRole::Questions), std::to_string(translation.questions.size()) + " questions", translation.questions.size(), original.questions.size());
    compare(title, std::to_string(translation.steps.size()) + " steps", translation.steps.size(), original.steps.size());
    for (std::size_t i = 0; i < std::min(translation.steps.size(), original.steps.size()); ++i) {
        const LessonStep& t = translation.steps[i];
        const LessonStep& o = original.steps[i];
        const std::string step = "step " + std::to_string(i + 1);
        compare(t.line, step + (t.optional ? " (optional)" : " (core)"), t.optional, o.optional);
        compare(t.line, step + "'s " + std::to_string(t.commands.size()) + " commands", t.commands.size(), o.commands.size());
        for (std::size_t k = 0; k < std::min(t.commands.size(), o.commands.size()); ++k)
            compare(t.commands[k].line, step + "'s '" + commandText(t.commands[k]) + "'", commandText(t.commands[k]),
                    commandText(o.commands[k]));
    }
    compare(title, std::to_string(translation.pictures.size()) + " pictures", translation.pictures.size(), original.pictures.size());
    for (std::size_t i = 0; i < std::min(translation.pictures.size(), original.pictures.size()); ++i) {
        const LessonPicture& p = translation.pictures[i];
        compare(p.line, "picture " + std::to_string(i + 1) + " (" + translation.picturePath(p.source).string() + ")",
                translation.picturePath(p.source), original.picturePath(original.pictures[i].source));
    }
    compare(sectionLine(translation, LessonRole::Code), "the code track's exercises", translation.codeExercises, original.codeExercises);
    return out;
}

} // namespace raylab
