#include "exercise/manifest.h"

#include "exercise/checks.h"
#include "io/resource_directory.h"
#include "render/tracer_defines.h"

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace raylab {
namespace fs = std::filesystem;
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
    std::vector<std::string> parts;
    std::string part;
    std::istringstream in(s);
    while (std::getline(in, part, sep)) parts.push_back(part);
    if (!s.empty() && s.back() == sep) parts.emplace_back();
    return parts;
}

// The slots are the tracer's defines that this file sets (render/tracer_defines.h).
bool isSlot(const std::string& name) {
    for (const TracerDefine& d : kTracerDefines)
        if (d.name == name && d.setBy == "exercise/manifest.cpp") return true;
    return false;
}

} // namespace

fs::path exerciseDirectory() {
    return resourceDirectory(std::getenv("RAYLAB_EXERCISE_DIR"), "exercises", "manifest.tsv",
                             fs::path(RAYLAB_SOURCE_SHADER_DIR).parent_path() / "exercises");
}

std::vector<Exercise> loadManifest(const fs::path& file) {
    std::ifstream in(file);
    if (!in) throw std::runtime_error(file.string() + ": error: cannot read the exercise manifest");
    std::vector<Exercise> out;
    std::string line;
    for (int lineNo = 1; std::getline(in, line); ++lineNo) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> cols = split(line, '\t');
        // Column c starts after c tabs: the 1-based column of its first character.
        auto where = [&](std::size_t c) {
            std::size_t col = 1;
            for (std::size_t i = 0; i < c && i < cols.size(); ++i) col += cols[i].size() + 1;
            return file.string() + ":" + std::to_string(lineNo) + ":" + std::to_string(col) + ": error: ";
        };
        if (cols.size() != 6)
            throw std::runtime_error(where(0) + "expected 6 tab-separated columns (name, slot, file, level, minutes, checks), found " +
                                     std::to_string(cols.size()));
        Exercise e{cols[0], cols[1], cols[2], cols[3], 0, {}};
        if (e.name.empty()) throw std::runtime_error(where(0) + "empty exercise name");
        if (findExercise(out, e.name)) throw std::runtime_error(where(0) + "exercise \"" + e.name + "\" is listed twice");
        if (!isSlot(e.slot))
            throw std::runtime_error(where(1) + "unknown slot \"" + e.slot +
                                     "\" (the RAYLAB_EXERCISE_ defines of render/tracer_defines.h)");
        if (e.file.empty() || e.file.find('/') != std::string::npos)
            throw std::runtime_error(where(2) + "the pupil file must be a plain file name, got \"" + e.file + "\"");
        try {
            std::size_t used = 0;
            e.minutes = std::stoi(cols[4], &used);
            if (used != cols[4].size() || e.minutes <= 0) throw std::invalid_argument("");
        } catch (const std::exception&) {
            throw std::runtime_error(where(4) + "minutes must be a positive whole number, got \"" + cols[4] + "\"");
        }
        for (const std::string& c : split(cols[5], ',')) {
            if (!findExerciseCheck(c))
                throw std::runtime_error(where(5) + "unknown check \"" + c + "\" (exercise/checks.cpp)");
            e.checks.push_back(c);
        }
        out.push_back(std::move(e));
    }
    return out;
}

std::vector<Exercise> loadManifest() { return loadManifest(exerciseDirectory() / "manifest.tsv"); }

const Exercise* findExercise(const std::vector<Exercise>& exercises, const std::string& name) {
    for (const Exercise& e : exercises)
        if (e.name == name) return &e;
    return nullptr;
}

} // namespace raylab
