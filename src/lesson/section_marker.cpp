#include "lesson/section_marker.h"

#include <algorithm>
#include <iterator>
#include <sstream>
#include <vector>

namespace raylab {
namespace {

std::string trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r\n");
    if (first == std::string_view::npos) return {};
    return std::string(s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1));
}

} // namespace

std::string roleMarker(LessonRole role) {
    for (const LessonRoleMarker& m : kLessonRoleMarkers)
        if (m.role == role) return m.marker;
    return {};
}

std::string roleMarkerList() {
    std::string s;
    for (const LessonRoleMarker& m : kLessonRoleMarkers) {
        s += (s.empty() ? "" : ", ") + std::string(m.marker);
        if (m.role == LessonRole::Step) s += ", {#step .optional}";
    }
    return s;
}

std::variant<MarkedHeading, std::string> parseMarkedHeading(std::string_view text) {
    const std::string heading = trim(text);
    const std::string markers = "; end a '## ' heading in one of " + roleMarkerList();
    const auto open = heading.rfind('{');
    if (open != std::string::npos && heading.compare(open, 2, "{#") == 0 && heading.back() != '}')
        return "malformed marker '" + heading.substr(open) + "' (write {#ROLE}, or {#step .optional})" + markers;
    if (heading.empty() || heading.back() != '}' || open == std::string::npos)
        return "the heading '" + heading + "' has no role marker" + markers;
    const std::string marker = heading.substr(open);
    std::istringstream words(marker.substr(1, marker.size() - 2));
    std::vector<std::string> parts;
    for (std::string word; words >> word;) parts.push_back(word);
    if (parts.empty() || parts[0].size() < 2 || parts[0][0] != '#')
        return "malformed marker '" + marker + "' (write {#ROLE}, or {#step .optional})" + markers;
    MarkedHeading h;
    h.text = trim(std::string_view(heading).substr(0, open));
    const std::string role = "{" + parts[0] + "}";
    const auto known = std::find_if(std::begin(kLessonRoleMarkers), std::end(kLessonRoleMarkers),
                                    [&](const LessonRoleMarker& m) { return role == m.marker; });
    if (known == std::end(kLessonRoleMarkers)) return "unknown role '" + parts[0] + "' in '" + marker + "'" + markers;
    h.role = known->role;
    for (std::size_t i = 1; i < parts.size(); ++i) {
        if (parts[i] != ".optional" || h.role != LessonRole::Step || h.optional)
            return "unknown class '" + parts[i] + "' in '" + marker + "' (only a step takes '.optional', once)" + markers;
        h.optional = true;
    }
    if (h.text.empty()) return "the marker '" + marker + "' has no heading before it";
    return h;
}

std::size_t sectionMarkerStart(std::string_view heading) {
    const auto end = heading.find_last_not_of(" \t\r\n");
    if (end == std::string_view::npos || heading[end] != '}') return heading.size();
    const auto open = heading.rfind('{', end);
    if (open == std::string_view::npos || heading.compare(open, 2, "{#") != 0) return heading.size();
    const auto before = heading.find_last_not_of(" \t", open == 0 ? 0 : open - 1);
    return open == 0 || before == std::string_view::npos ? 0 : before + 1;
}

std::string withoutSectionMarker(std::string_view heading) { return trim(heading.substr(0, sectionMarkerStart(heading))); }

} // namespace raylab
