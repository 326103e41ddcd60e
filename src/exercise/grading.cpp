#include "exercise/grading.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace raylab {
namespace fs = std::filesystem;
namespace {

// The compiler's lines that name the pupil's file; all of them when none does.
std::string pupilLines(const std::string& log, const fs::path& file) {
    std::istringstream in(log);
    std::string line, out;
    const std::string name = fs::weakly_canonical(file).string();
    while (std::getline(in, line))
        if (line.find(name) != std::string::npos) out += line + "\n";
    return out.empty() ? log : out;
}

bool hasPupilFiles(const fs::path& dir, const std::vector<Exercise>& exercises) {
    return std::any_of(exercises.begin(), exercises.end(), [&](const Exercise& e) { return fs::is_regular_file(dir / e.file); });
}

PupilReport gradePupil(const fs::path& dir, const std::vector<Exercise>& exercises, const fs::path& imageDir) {
    PupilReport p{fs::weakly_canonical(dir).filename().string(), {}};
    const fs::path images = imageDir.empty() ? imageDir : imageDir / p.pupil;
    for (const Exercise& e : exercises)
        if (fs::is_regular_file(dir / e.file)) p.exercises.push_back(checkExercise(e, dir / e.file, images));
    return p;
}

std::string csvField(const std::string& s) {
    std::string q = "\"";
    for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

// A Markdown table cell: one line, its bars escaped.
std::string oneLine(const std::string& s) {
    std::string out;
    for (char c : s) out += c == '\n' ? std::string(" ") : c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

} // namespace

bool ExerciseReport::pass() const {
    return compiled && std::all_of(checks.begin(), checks.end(), [](const CheckResult& c) { return c.pass; });
}

ExerciseReport checkExercise(const Exercise& exercise, const fs::path& pupilFile, const fs::path& imageDir) {
    ExerciseReport r{exercise.name, pupilFile, false, "", {}};
    try {
        const ExerciseProbe probe(exercise.slot, pupilFile);
        r.compiled = true;
        const CheckContext context{probe, exercise.slot, pupilFile, exercise.name, imageDir};
        for (const std::string& name : exercise.checks) r.checks.push_back(findExerciseCheck(name)->run(context));
    } catch (const ShaderError& e) {
        r.compileError = pupilLines(e.what(), pupilFile);
    }
    return r;
}

std::vector<PupilReport> gradeFolder(const fs::path& dir, const std::vector<Exercise>& exercises, const fs::path& imageDir) {
    if (!fs::is_directory(dir)) throw std::runtime_error(dir.string() + ": error: not a folder of pupil files");
    if (hasPupilFiles(dir, exercises)) return {gradePupil(dir, exercises, imageDir)};
    std::vector<fs::path> pupils;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.is_directory() && hasPupilFiles(e.path(), exercises)) pupils.push_back(e.path());
    std::sort(pupils.begin(), pupils.end());
    if (pupils.empty())
        throw std::runtime_error(dir.string() + ": error: no pupil files: expected files named as in the manifest (e.g. " +
                                 (exercises.empty() ? std::string("01-ray-sphere.glsl") : exercises.front().file) +
                                 "), in this folder or in one sub-folder per pupil");
    std::vector<PupilReport> out;
    for (const fs::path& p : pupils) out.push_back(gradePupil(p, exercises, imageDir));
    return out;
}

std::string reportMarkdown(const std::vector<PupilReport>& pupils) {
    std::ostringstream out;
    for (const PupilReport& p : pupils) {
        int passed = 0;
        for (const auto& e : p.exercises) passed += e.pass() ? 1 : 0;
        out << "## " << p.pupil << ": " << passed << " of " << p.exercises.size() << " exercises pass\n\n";
        out << "| exercise | check | verdict | numbers | message |\n|---|---|---|---|---|\n";
        for (const ExerciseReport& e : p.exercises) {
            if (!e.compiled) {
                out << "| " << e.exercise << " | compile | FAIL | | " << oneLine(e.compileError) << " |\n";
                continue;
            }
            for (const CheckResult& c : e.checks)
                out << "| " << e.exercise << " | " << c.check << " | " << (c.pass ? "pass" : "FAIL") << " | "
                    << oneLine(c.numbers) << " | " << oneLine(c.message) << (c.image.empty() ? "" : " (picture: " + c.image + ")")
                    << " |\n";
        }
        out << "\n";
    }
    return out.str();
}

std::string reportCsv(const std::vector<PupilReport>& pupils) {
    std::ostringstream out;
    out << "pupil,exercise,check,verdict,numbers,message,picture\n";
    for (const PupilReport& p : pupils)
        for (const ExerciseReport& e : p.exercises) {
            if (!e.compiled) {
                out << csvField(p.pupil) << "," << csvField(e.exercise) << ",compile,fail,," << csvField(e.compileError) << ",\n";
                continue;
            }
            for (const CheckResult& c : e.checks)
                out << csvField(p.pupil) << "," << csvField(e.exercise) << "," << csvField(c.check) << ","
                    << (c.pass ? "pass" : "fail") << "," << csvField(c.numbers) << "," << csvField(c.message) << ","
                    << csvField(c.image) << "\n";
        }
    return out.str();
}

} // namespace raylab
