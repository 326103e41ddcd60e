#include "scene/scene_error.h"

#include "scene/parameters.h"
#include "scene/scene_overrides.h"

#include <utility>

namespace raylab::scenefmt {

void fail(const JsonPath& path, std::string message, bool atKey) {
    throw ValidationFailure{path, std::move(message), atKey};
}

std::string inQuotes(std::string_view s) { return "'" + shortText(s) + "'"; }

std::string joinNames(const std::vector<std::string_view>& names) {
    std::string out;
    for (std::string_view n : names) {
        if (!out.empty()) out += ", ";
        out += n;
    }
    return out;
}

std::string inWhere(const JsonPath& p) { return p.segments.empty() ? "at the top level" : "in " + p.display(); }

std::string suggestion(std::string_view word, const std::vector<std::string_view>& candidates,
                       std::string_view listName) {
    const std::string_view best = closestMatch(word, candidates);
    if (!best.empty()) return "; did you mean " + inQuotes(best) + "?";
    if (candidates.empty()) return " (there are no " + std::string(listName) + ")";
    return " (" + std::string(listName) + ": " + joinNames(candidates) + ")";
}

std::string fileLocation(const std::string& fileName, SourcePos pos) {
    return fileName + ":" + std::to_string(pos.line) + ":" + std::to_string(pos.column) + ": error: ";
}

void failUnknownKey(const JsonPath& path, std::string_view key, const std::vector<std::string_view>& known) {
    fail(path.key(key), "unknown key " + inQuotes(key) + " " + inWhere(path) + suggestion(key, known, "known keys"), true);
}

std::string documentError(const ParseResult& parsed, const JsonLocator& locator, const std::string& fileName) {
    if (!parsed.ok) {
        const std::string where = fileLocation(fileName, locator.position(parsed.errorOffset));
        return where + (parsed.errorPath ? parsed.errorPath->display() + ": " : std::string()) + parsed.reason;
    }
    if (locator.duplicates().empty()) return {};
    const JsonLocator::Duplicate& d = locator.duplicates().front();
    const JsonPath p = pathFromPointer(parsed.doc, d.pointer);
    return fileLocation(fileName, d.second) + p.display() + ": duplicate key " + inQuotes(p.segments.back().token) +
           " (first given at line " + std::to_string(d.first.line) + ", column " + std::to_string(d.first.column) + ")";
}

std::string overridePrefix(const std::string& text) { return "--set " + text + ": error: "; }

std::string placeFailure(const ValidationFailure& f, const std::string& fileName, const JsonLocator& locator,
                         const std::vector<AppliedOverride>& overrides) {
    const std::string pointer = f.path.pointer();
    const std::string tail = f.path.display() + ": " + f.message;
    for (auto it = overrides.rbegin(); it != overrides.rend(); ++it)
        if (isPointerPrefix(it->pointer, pointer)) return overridePrefix(it->text) + tail;
    if (const ValueLocation* loc = locator.find(pointer))
        return fileLocation(fileName, f.atKey && loc->key.valid() ? loc->key : loc->value) + tail;
    for (auto it = overrides.rbegin(); it != overrides.rend(); ++it)
        if (isPointerPrefix(pointer, it->pointer)) return overridePrefix(it->text) + tail;
    // Cross-field checks (camera.up against camera.position) blame a sibling set by an override.
    const std::string parentPointer = pointer.substr(0, pointer.rfind('/'));
    for (auto it = overrides.rbegin(); it != overrides.rend(); ++it)
        if (!pointer.empty() && it->pointer.substr(0, it->pointer.rfind('/')) == parentPointer)
            return overridePrefix(it->text) + tail;
    JsonPath parent = f.path;
    while (!parent.segments.empty()) {
        parent.segments.pop_back();
        if (const ValueLocation* loc = locator.find(parent.pointer())) return fileLocation(fileName, loc->value) + tail;
    }
    return fileLocation(fileName, SourcePos{1, 1}) + tail;
}

} // namespace raylab::scenefmt
