// The code track's checks against its own exercises: every reference solution passes every check,
// every shipped stub fails one, and each plausible wrong answer (tests/data/exercises/wrong_answers.tsv:
// a solution with an edit) fails the check it names with a message that names the mistake.
#include "exercise/grading.h"
#include "exercise/manifest.h"
#include "render/path_tracer.h"
#include "scene/scene_loader.h"
#include "support/gl_test.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

const fs::path kRoot = RAYLAB_SOURCE_DIR;
const fs::path kAnswers = kRoot / "tests/data/exercises/wrong_answers.tsv";

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
    }
}

TEST(ExerciseManifest, BadRowsGiveLocatedErrors) {
    const fs::path file = fs::temp_directory_path() / "raylab_bad_manifest.tsv";
    const std::pair<std::string, std::string> rows[] = {
        {"a\tRAYLAB_EXERCISE_NOPE\ta.glsl\tVWO 5-6\t5\tsphere-rays", ":2:3: error: unknown slot \"RAYLAB_EXERCISE_NOPE\""},
        {"a\tRAYLAB_EXERCISE_RAY_SPHERE\ta.glsl\tVWO 5-6\tten\tsphere-rays", ":2:45: error: minutes"},
        {"a\tRAYLAB_EXERCISE_RAY_SPHERE\ta.glsl\tVWO 5-6\t5\tsphere-rayz", ":2:47: error: unknown check \"sphere-rayz\""},
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
TEST_F(ExerciseChecks, TheWholeTracerCompilesAndRendersWithEverySolutionInItsSlot) {
    // All features on, so that every slot is compiled in; the image must be finite and lit.
    Scene scene = loadScene(kRoot / "exercises/render_check.json");
    scene.render.spp = 4;
    for (const Exercise& e : loadManifest(kRoot / "exercises/manifest.tsv")) {
        TracerOptions o;
        o.specialise = false;
        o.extraDefines = {{e.slot, "\"" + (kRoot / "exercises/solutions" / e.file).string() + "\""}};
        PathTracer tracer(o);
        ASSERT_NO_THROW(tracer.setScene(scene)) << e.name;
        tracer.renderPass(4);
        const Image image = tracer.readImage();
        double sum = 0.0;
        for (float v : image.rgba) sum += v;
        EXPECT_TRUE(std::isfinite(sum) && sum > 0.0) << e.name << ": image sum " << sum;
        EXPECT_EQ(tracer.nonFiniteSamples(), 0u) << e.name;
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
    const fs::path scratch = fs::temp_directory_path() / ("raylab_wrong_answers_" + std::to_string(::getpid()));
    std::ifstream in(kAnswers);
    std::string line;
    std::map<std::string, int> perExercise;
    std::map<std::string, ExerciseReport> reports;   // by exercise/mistake
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::vector<std::string> cols;
        std::istringstream row(line);
        for (std::string col; std::getline(row, col, '\t');) cols.push_back(col);
        ASSERT_GE(cols.size(), 5u) << line;
        const std::string& name = cols[0];
        const std::string key = name + "/" + cols[1], check = cols[2], message = cols[3];
        const Exercise* e = findExercise(exercises, name);
        ASSERT_NE(e, nullptr) << line;
        if (!reports.count(key)) {
            // The solution with the row's edits, under the pupil file's own name.
            std::ifstream solution(kRoot / "exercises/solutions" / e->file);
            std::string text((std::istreambuf_iterator<char>(solution)), std::istreambuf_iterator<char>());
            for (std::size_t i = 4; i < cols.size(); ++i) {
                const auto arrow = cols[i].find(" => ");
                ASSERT_NE(arrow, std::string::npos) << cols[i];
                const std::string from = cols[i].substr(0, arrow), to = cols[i].substr(arrow + 4);
                ASSERT_NE(text.find(from), std::string::npos) << key << ": \"" << from << "\" is not in the solution";
                for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
                    text.replace(at, from.size(), to);
            }
            fs::create_directories(scratch / key);
            std::ofstream(scratch / key / e->file) << text;
            reports.emplace(key, checkExercise(*e, scratch / key / e->file));
            ++perExercise[name];
        }
        const ExerciseReport& r = reports.at(key);
        SCOPED_TRACE(key + "\n" + summary(r));
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
    // Every exercise has at least three wrong answers, each caught.
    for (const Exercise& e : exercises) EXPECT_GE(perExercise[e.name], 3) << e.name;
    fs::remove_all(scratch);
}
