// raylab-exercise as a teacher runs it: the list, a graded folder, and located errors on bad input.
#include "support/render_cli.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace raylab::test;
namespace fs = std::filesystem;

namespace {

CliRun exercise(const std::string& args, const fs::path& dir) { return runProgram(RAYLAB_EXERCISE_EXE, args, dir); }

} // namespace

TEST(ExerciseCli, ListPrintsTheManifest) {
    const fs::path dir = scratchDir("raylab_exercise_list");
    const CliRun r = exercise("list", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_NE(r.out.find("ray-sphere\tRAYLAB_EXERCISE_RAY_SPHERE\t01-ray-sphere.glsl\tVWO 5-6\t45"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("running-mean"), std::string::npos);
    fs::remove_all(dir);
}

TEST(ExerciseCli, GradesOneSubFolderPerPupilIntoACsvTable) {
    const fs::path dir = scratchDir("raylab_exercise_grade");
    fs::create_directories(dir / "class/ada");
    fs::create_directories(dir / "class/bob");
    fs::copy_file(fs::path(RAYLAB_SOURCE_DIR) / "exercises/solutions/05-lambert.glsl", dir / "class/ada/05-lambert.glsl");
    std::ofstream(dir / "class/bob/05-lambert.glsl") << "vec3 lambertBrdf(vec3 albedo, vec3 wo, vec3 wi) { return albedo; }\n";
    const CliRun r = exercise("check '" + (dir / "class").string() + "' --out '" + (dir / "grades.csv").string() + "'", dir);
    EXPECT_EQ(r.status, 0) << r.err;
    const std::string csv = slurp(dir / "grades.csv");
    EXPECT_NE(csv.find("\"ada\",\"lambert\",\"furnace\",pass"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\"bob\",\"lambert\",\"furnace\",fail"), std::string::npos) << csv;
    EXPECT_NE(csv.find("energy π: f misses the 1/π"), std::string::npos) << csv;
    fs::remove_all(dir);
}

TEST(ExerciseCli, BadInputExitsNonZeroWithALocatedMessage) {
    const fs::path dir = scratchDir("raylab_exercise_bad");
    fs::create_directories(dir / "empty");
    CliRun r = exercise("check '" + (dir / "empty").string() + "'", dir);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find((dir / "empty").string() + ": error: no pupil files"), std::string::npos) << r.err;
    r = exercise("check '" + (dir / "nowhere").string() + "'", dir);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("nowhere: error: not a folder"), std::string::npos) << r.err;
    r = exercise("check '" + (dir / "empty").string() + "' --out grades.txt", dir);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("grades.txt: error: --out must end in .md or .csv"), std::string::npos) << r.err;
    std::ofstream(dir / "manifest.tsv") << "lambert\tRAYLAB_EXERCISE_LAMBERT\t05-lambert.glsl\tVWO 5-6\t20\tfurnaec\n";
    r = exercise("--manifest '" + (dir / "manifest.tsv").string() + "' list", dir);
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("manifest.tsv:1:60: error: unknown check \"furnaec\""), std::string::npos) << r.err;
    fs::remove_all(dir);
}
