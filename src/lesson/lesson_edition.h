#pragma once
// A lesson's editions: the English lessons in lessons/, each other language's in lessons/LANG/
// under the same file name, with the same scene, steps and ```raylab blocks and the same pictures
// (lessons/README.md). The drift test holds every translation to its original with this.
#include "lesson/lesson.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raylab {

// The folder of `language`'s edition: `lessons` itself for English, `lessons`/LANG otherwise.
std::filesystem::path lessonEditionFolder(const std::filesystem::path& lessons, std::string_view language);

// The same lesson in `language`'s edition (the file need not exist); nullopt when `file` lies in
// no edition's folder (lessons/X.md, lessons/LANG/X.md).
std::optional<std::filesystem::path> lessonInLanguage(const std::filesystem::path& file, std::string_view language);

// How `translation` drifts from `original`, one "FILE:LINE: what" a difference (none: they agree):
// scene, level and minutes; the sections' roles in order; the number of goals and questions; the
// steps, their optional marks and every command of their ```raylab blocks (holds included); the
// pictures' files in order; the code track's exercises; and the translation's `Language:`.
std::vector<std::string> editionDifferences(const Lesson& original, const Lesson& translation);

} // namespace raylab
