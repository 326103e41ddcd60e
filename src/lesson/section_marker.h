#pragma once
// The role marker that ends a lesson's `## ` heading, in Pandoc's attribute syntax:
// `## Learning goals {#goals}`, `## Stap 4: De renderer {#step .optional}`. The loader takes a
// section's role from it, never from the heading's words, so every language's edition loads alike.
#include <cstddef>
#include <string>
#include <string_view>
#include <variant>

namespace raylab {

enum class LessonRole { Goals, Step, Questions, Exercise, Code, Further, Notes, Sources };

struct LessonRoleMarker {
    LessonRole role;
    const char* marker;                   // "{#goals}"
};
// Every role's marker, in the order sections appear; a step may also be `{#step .optional}`.
inline constexpr LessonRoleMarker kLessonRoleMarkers[] = {
    {LessonRole::Goals, "{#goals}"},       {LessonRole::Step, "{#step}"},       {LessonRole::Questions, "{#questions}"},
    {LessonRole::Exercise, "{#exercise}"}, {LessonRole::Code, "{#code}"},       {LessonRole::Further, "{#further}"},
    {LessonRole::Notes, "{#notes}"},       {LessonRole::Sources, "{#sources}"},
};

// "{#goals}"
std::string roleMarker(LessonRole role);
// "{#goals}, {#step}, {#step .optional}, ...": for messages.
std::string roleMarkerList();

struct MarkedHeading {
    std::string text;                     // the heading without the marker
    LessonRole role = LessonRole::Goals;
    bool optional = false;                // `.optional`
};

// "TEXT {#ROLE}" or "TEXT {#step .optional}"; otherwise what is wrong (no marker, malformed, an
// unknown role or class), the markers listed.
std::variant<MarkedHeading, std::string> parseMarkedHeading(std::string_view heading);

// Where a heading's trailing `{#...}` marker, with the spaces before it, starts; its size if none.
std::size_t sectionMarkerStart(std::string_view heading);
// The heading without that marker, trimmed.
std::string withoutSectionMarker(std::string_view heading);

} // namespace raylab
