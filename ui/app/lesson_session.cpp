#include "app/lesson_session.h"

#include "lesson/lesson_edition.h"

#include <algorithm>

namespace raylab::ui {

void LessonSession::scan(const std::filesystem::path& lessons) {
    lessons_ = lessons;
    entries_.clear();
    std::error_code ec;
    std::vector<std::filesystem::path> files;
    for (const auto& e : std::filesystem::directory_iterator(lessonEditionFolder(lessons, language_), ec))
        if (e.path().extension() == ".md" && e.path().filename() != "README.md") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    for (const auto& f : files) {
        LessonEntry entry{f, "", ""};
        try {
            entry.title = loadLesson(f).title;
        } catch (const std::exception& e) {
            entry.error = e.what();
        }
        entries_.push_back(std::move(entry));
    }
}

std::optional<std::string> LessonSession::open(const std::filesystem::path& file) {
    try {
        lesson_ = loadLesson(file);
    } catch (const std::exception& e) {
        return std::string(e.what());
    }
    current_ = -1;
    part_ = 0;
    pending_.reset();
    if (lesson_->language != language_) {
        language_ = lesson_->language;
        if (!lessons_.empty()) scan(lessons_);
    }
    return std::nullopt;
}

std::optional<std::string> LessonSession::setLanguage(const std::string& language) {
    if (!isLessonLanguage(language)) return "unknown lesson language '" + language + "' (" + lessonLanguageList() + ")";
    if (isOpen() && lesson_->language != language) {
        const auto twin = lessonInLanguage(lesson_->file, language);
        if (!twin)
            return lesson_->file.string() + ": error: the lesson is in no lessons folder, so it has no '" + language + "' edition";
        try {
            Lesson translated = loadLesson(*twin);
            if (current_ >= int(translated.steps.size()) ||
                (current_ >= 0 && part_ >= translated.steps[std::size_t(current_)].partCount()))
                return twin->string() + ": error: its steps differ from " + lesson_->file.string() + "'s";
            lesson_ = std::move(translated);
        } catch (const std::exception& e) {
            return std::string(e.what());
        }
    }
    language_ = language;
    if (!lessons_.empty()) scan(lessons_);
    return std::nullopt;
}

int LessonSession::partCount(int step) const {
    return isOpen() && step >= 0 && step < stepCount() ? lesson_->steps[std::size_t(step)].partCount() : 0;
}

bool LessonSession::next() {
    if (current_ >= 0 && part_ + 1 < partCount(current_)) return apply(current_, part_ + 1);
    return apply(current_ + 1);
}

bool LessonSession::previous() {
    if (current_ < 0) return apply(0);
    if (part_ > 0) return apply(current_, part_ - 1);
    return apply(current_ - 1, partCount(current_ - 1) - 1);
}

bool LessonSession::apply(int i, int part) {
    if (!isOpen() || i < 0 || i >= stepCount() || part < 0 || part >= partCount(i)) return false;
    current_ = i;
    part_ = part;
    const LessonStep& step = lesson_->steps[std::size_t(i)];
    std::vector<ScriptCommand> script = lessonResetCommands();
    if (step.commands.empty() || step.commands.front().name != "open")
        script.push_back(ScriptCommand{step.line, "open", {lesson_->scenePath.string()}});
    for (ScriptCommand c : step.partScript(part)) {
        if (c.name == "open") c.args[0] = lesson_->resolve(c.args[0]).string();
        script.push_back(std::move(c));
    }
    pending_ = std::move(script);
    return true;
}

std::optional<std::vector<ScriptCommand>> LessonSession::takeScript() {
    auto s = std::move(pending_);
    pending_.reset();
    return s;
}

std::filesystem::path defaultLessonDirectory(const std::filesystem::path& shaderDirectory) {
    std::error_code ec;
    const std::filesystem::path dir = std::filesystem::weakly_canonical(shaderDirectory / ".." / "lessons", ec);
    return ec ? shaderDirectory / ".." / "lessons" : dir;
}

std::vector<ScriptCommand> lessonResetCommands() {
    return parseScript("debug-view beauty\noverlay boxes off\noverlay selected off\nbounce-step off\nsplit off\nresume\n",
                       "lesson reset");
}

} // namespace raylab::ui
