// The code track's checks against its own exercises: every reference solution passes every check,
// every shipped stub fails one, and each plausible wrong answer (tests/data/exercises/wrong/) fails
// the check expected.tsv names with a message that names the mistake.
#include "exercise/grading.h"
#include "exercise/manifest.h"
#include "support/gl_test.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

const fs::path kRoot = RAYLAB_SOURCE_DIR;
const fs::path kWrong = kRoot / "tests/data/exercises/wrong";

std::string summary(const ExerciseReport& r) {
    std::string s = r.compiled ? "" : "compile error: " + r.compileError;
    for (const CheckResult& c : r.checks)
        s += c.check + (c.pass ? " pass: " : " FAIL: ") + c.numbers + (c.message.empty() ? "" : " — " + c.message) + "\n";
    return s;
}

class ExerciseChecks : public test::GlTest {};

} // namespace

TEST(ExerciseManifest, ListsEveryExerciseWithItsStubAndSolution) {
    const auto exercises = loadManifest(kRoot / "exercises/manifest.tsv");
    ASSERT_EQ(exercises.size(), 10u);
    for (const Exercise& e : exercises) {
        EXPECT_TRUE(fs::is_regular_file(kRoot / "exercises" / e.file)) << e.file;
        EXPECT_TRUE(fs::is_regular_file(kRoot / "exercises/solutions" / e.file)) << e.file;
        EXPECT_TRUE(e.level == "VWO 5-6" || e.level == "first-year university") << e.name << ": " << e.level;
        EXPECT_TRUE(fs::is_directory(kWrong / e.name)) << e.name << " has no wrong answers";
    }
}

TEST(ExerciseManifest, BadRowsGiveLocatedErrors) {
    const fs::path file = fs::temp_directory_path() / "raylab_bad_manifest.tsv";
    const std::pair<std::string, std::string> rows[] = {
        {"a\tRAYLAB_EXERCISE_NOPE\ta.glsl\tVWO 5-6\t5\tsphere-rays", ":2:3: error: unknown slot \"RAYLAB_EXERCISE_NOPE\""},
        {"a\tRAYLAB_EXERCISE_RAY_SPHERE\ta.glsl\tVWO 5-6\tten\tsphere-rays", ":2:51: error: minutes"},
        {"a\tRAYLAB_EXERCISE_RAY_SPHERE\ta.glsl\tVWO 5-6\t5\tsphere-rayz", ":2:53: error: unknown check \"sphere-rayz\""},
        {"a\tRAYLAB_EXERCISE_RAY_SPHERE\ta.glsl", ":2:1: error: expected 6 tab-separated columns"},
    };
    for (const auto& [row, message] : rows) {
        std::ofstream(file) << "# comment\n" << row << "\n";
        try {
            loadManifest(file);
            ADD_FAILURE() << "accepted: " << row;
        } catch (const std::runtime_error& e) {
            EXPECT_NE(std::string(e.what()).find(file.string() + message), std::string::npos) << e.what();
        }
    }
    fs::remove(file);
}

// ctest: slow
TEST_F(ExerciseChecks, EveryReferenceSolutionPassesEveryCheck) {
    for (const Exercise& e : loadManifest(kRoot / "exercises/manifest.tsv")) {
        const ExerciseReport r = checkExercise(e, kRoot / "exercises/solutions" / e.file);
        EXPECT_TRUE(r.pass()) << e.name << ":\n" << summary(r);
        EXPECT_EQ(r.checks.size(), e.checks.size()) << e.name;
    }
}

// ctest: slow
TEST_F(ExerciseChecks, EveryShippedStubCompilesAndFailsACheck) {
    for (const Exercise& e : loadManifest(kRoot / "exercises/manifest.tsv")) {
        const ExerciseReport r = checkExercise(e, kRoot / "exercises" / e.file);
        EXPECT_TRUE(r.compiled) << e.name << ": " << r.compileError;
        EXPECT_FALSE(r.pass()) << e.name << ":\n" << summary(r);
    }
}

// ctest: slow
TEST_F(ExerciseChecks, PlausibleWrongAnswersAreCaughtWithAMessageThatNamesTheMistake) {
    const auto exercises = loadManifest(kRoot / "exercises/manifest.tsv");
    std::ifstream in(kWrong / "expected.tsv");
    std::string line;
    std::map<std::string, int> perExercise;
    std::map<std::string, ExerciseReport> reports;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream row(line);
        std::string file, check, message;
        std::getline(row, file, '\t');
        std::getline(row, check, '\t');
        std::getline(row, message);
        const std::string name = fs::path(file).parent_path().string();
        const Exercise* e = findExercise(exercises, name);
        ASSERT_NE(e, nullptr) << file;
        if (!reports.count(file)) {
            reports.emplace(file, checkExercise(*e, kWrong / file));
            ++perExercise[name];
        }
        const ExerciseReport& r = reports.at(file);
        SCOPED_TRACE(file + "\n" + summary(r));
        if (check == "compile") {
            EXPECT_FALSE(r.compiled);
            EXPECT_NE(r.compileError.find(message), std::string::npos);
            continue;
        }
        ASSERT_TRUE(r.compiled) << r.compileError;
        bool found = false;
        for (const CheckResult& c : r.checks)
            if (c.check == check) {
                found = true;
                EXPECT_FALSE(c.pass);
                EXPECT_NE(c.message.find(message), std::string::npos) << "expected \"" << message << "\"";
            }
        EXPECT_TRUE(found) << "no check " << check;
    }
    // Every exercise has at least three wrong answers that compile and are caught.
    for (const Exercise& e : exercises) EXPECT_GE(perExercise[e.name], 3) << e.name;
    // Every file in wrong/ is listed.
    for (const auto& entry : fs::recursive_directory_iterator(kWrong)) {
        if (entry.path().extension() != ".glsl") continue;
        EXPECT_TRUE(reports.count(fs::relative(entry.path(), kWrong).string())) << entry.path() << " is not in expected.tsv";
    }
}
