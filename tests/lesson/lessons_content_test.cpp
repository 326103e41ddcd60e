// The shipped lessons (lessons/*.md): every lesson loads, its scene loads, every step's commands
// parse, and every `set KEY VALUE` of a step applies to the scene the step has open through the
// loader's --set mechanism (loadScene(scene, {"KEY=VALUE", ...}), the earlier sets of the step
// included, as the viewer would apply them). Scenes a step opens must load too.
#include "exercise/manifest.h"
#include "lesson/lesson.h"
#include "render/shader_variant.h"
#include "scene/scene_loader.h"
#include "script/expectation.h"
#include "shaders/include/russian_roulette.glsl"
#include "shaders/include/tone_map.glsl"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <string>
#include <vector>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

const fs::path kLessons = fs::path(RAYLAB_SOURCE_DIR) / "lessons";

// Scenes and keys the lessons use that exist only on other branches, so the checks above must fail
// for them on this branch. `what` is a scene path (as `open` gives it) or a `set` key, where `*`
// stands for one dotted part (a material name, an object index). A step that opens a listed scene
// cannot have its later commands checked here: they are covered by that scene's entry.
// Each entry must still fail here (an entry that starts to apply is reported, so the list stays
// exact) and each must be used by some lesson.
// remove when issue-materials / issue-geometry are merged
struct NeedsOtherBranch {
    const char* lesson;   // file name in lessons/
    const char* what;     // scene path or key pattern
    const char* branch;   // the branch that brings it
};
const std::vector<NeedsOtherBranch> kNeedsOtherBranches = {
};

bool keyMatches(const std::string& pattern, const std::string& key) {
    std::istringstream p(pattern), k(key);
    std::string a, b;
    while (true) {
        const bool morePattern = bool(std::getline(p, a, '.'));
        const bool moreKey = bool(std::getline(k, b, '.'));
        if (!morePattern || !moreKey) return morePattern == moreKey;
        if (a != "*" && a != b) return false;
    }
}

// Index into kNeedsOtherBranches, or -1.
int allowListed(const std::string& lesson, const std::string& what) {
    for (size_t i = 0; i < kNeedsOtherBranches.size(); ++i) {
        const auto& e = kNeedsOtherBranches[i];
        if (e.lesson == lesson && (e.what == what || keyMatches(e.what, what))) return int(i);
    }
    return -1;
}

std::string loadError(const fs::path& scene, const std::vector<std::string>& overrides) {
    try {
        loadScene(scene, overrides);
    } catch (const SceneError& e) {
        return e.what();
    }
    return {};
}

// Number of entries in the scene file's "objects" array (meshes included, whatever the branch).
size_t objectCount(const fs::path& scene) {
    std::ifstream in(scene);
    const auto doc = nlohmann::json::parse(in, nullptr, true, /*ignore_comments=*/true);
    return doc.contains("objects") ? doc["objects"].size() : 0;
}

std::string where(const Lesson& l, const ScriptCommand& c) {
    return l.file.filename().string() + ":" + std::to_string(c.line) + ": " + c.name;
}

// Runs every step of `lesson` against the scene loader; records which allow-list entries it used.
void checkSteps(const Lesson& lesson, std::set<int>& used) {
    const std::string name = lesson.file.filename().string();
    for (const LessonStep& step : lesson.steps) {
        fs::path scene = lesson.scenePath;   // a step starts on the lesson's scene
        bool elsewhere = false;              // the step opened an allow-listed scene
        std::vector<std::string> overrides;
        ViewState view;                      // a step starts from the default view (lessonResetCommands)
        for (ScriptCommand c : step.commands) {
            const std::string at = where(lesson, c);
            if (c.name == "stage") c = ScriptCommand{c.line, "set", {"render.stage", c.args[0]}};   // its meaning
            if ((c.name == "split-a" || c.name == "split-b") && !elsewhere) {
                // A side's override applies to the step's scene as it stands (the split screen checks it).
                std::vector<std::string> with = overrides;
                with.push_back(c.args[0] + "=" + c.args[1]);
                EXPECT_EQ(loadError(scene, with), "") << at << ": " << c.args[0] << " " << c.args[1];
                continue;
            }
            if (c.name == "open") {
                const fs::path path = lesson.resolve(c.args[0]);
                const std::string error = fs::exists(path) ? loadError(path, {}) : "missing";
                overrides.clear();
                if (const int i = allowListed(name, c.args[0]); i >= 0) {
                    used.insert(i);
                    EXPECT_FALSE(error.empty()) << at << ": " << c.args[0] << " now loads on this branch: remove it "
                                                << "from kNeedsOtherBranches";
                    elsewhere = true;
                    continue;
                }
                EXPECT_EQ(error, "") << at << ": " << c.args[0];
                scene = path;
                elsewhere = !error.empty();   // reported once; its later commands are not checked
            } else if (c.name == "set") {
                const std::string& key = c.args[0];
                EXPECT_NE(key.rfind("selected.", 0), 0u) << at << ": lessons use full keys, not selected.*";
                if (elsewhere) continue;
                std::vector<std::string> with = overrides;
                with.push_back(key + "=" + c.args[1]);
                const std::string error = loadError(scene, with);
                if (const int i = allowListed(name, key); i >= 0) {
                    used.insert(i);
                    EXPECT_FALSE(error.empty()) << at << ": " << key << " now applies on this branch: remove it from "
                                                << "kNeedsOtherBranches";
                } else {
                    EXPECT_EQ(error, "") << at << ": " << key << " " << c.args[1];
                    if (error.empty()) overrides = std::move(with);   // a failed set is not kept
                }
            } else if (c.name == "expect") {
                // The state the step's text describes holds here, as the script runner checks it.
                if (elsewhere) continue;
                try {
                    EXPECT_EQ(expectationFailure(loadScene(scene, overrides), view, c.args[0], c.args[1]), "") << at;
                } catch (const SceneError& e) {
                    ADD_FAILURE() << at << ": " << e.what();
                }
            } else if (c.name == "debug-view") {
                view.debugView = c.args[0];
            } else if (c.name == "bounce-step") {
                view.bounceStep = c.args[0] == "off" ? 0 : c.args[0] == "next" ? view.bounceStep + 1 : std::stoi(c.args[0]);
            } else if (c.name == "select") {
                if (elsewhere) continue;
                const double n = std::stod(c.args[0]);
                EXPECT_TRUE(n >= 0 && n < double(objectCount(scene)) && n == double(size_t(n)))
                    << at << ": no object " << c.args[0] << " in " << scene;
            } else if (c.name == "scale") {
                const double v = std::stod(c.args[0]);
                EXPECT_TRUE(v >= 0.125 && v <= 2) << at << ": scale is 0.125 to 2";
                view.scale = v;
            } else {
                // A lesson step sets state; it never ends the viewer or writes files.
                if (c.name == "hold") continue;   // sub-steps keep the state built so far
                for (const char* banned : {"quit", "screenshot", "export", "save", "window", "click", "ui-scale", "key",
                                           "lesson", "lesson-step", "self-test", "teach"})
                    EXPECT_NE(c.name, banned) << at << ": not for lessons";
            }
        }
    }
}

std::vector<std::string> lessonFileNames() {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(kLessons))
        if (e.path().extension() == ".md" && e.path().filename() != "README.md")
            names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

class ShippedLesson : public testing::TestWithParam<std::string> {};

std::string testName(const testing::TestParamInfo<std::string>& info) {
    std::string n = info.param.substr(0, info.param.size() - 3);
    for (char& ch : n)
        if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
    return n;
}

} // namespace

// Every lesson file loads, numbered 01, 02, … without a gap (the twelve of issue 6 first), and
// loadLessons gives them in file-name order.
TEST(Lessons, AllLoadInOrder) {
    const std::vector<Lesson> lessons = loadLessons(kLessons);
    ASSERT_GE(lessons.size(), 12u);
    ASSERT_EQ(lessons.size(), lessonFileNames().size());
    for (size_t i = 0; i < lessons.size(); ++i) {
        const std::string prefix = (i + 1 < 10 ? "0" : "") + std::to_string(i + 1) + "-";
        EXPECT_EQ(lessons[i].file.filename().string().rfind(prefix, 0), 0u) << lessons[i].file;
    }
}

// The code track (exercises/manifest.tsv): every exercise a lesson's "Write it yourself" opens
// exists, and every exercise is opened by some lesson.
TEST(Lessons, WriteItYourselfOpensEveryExercise) {
    const auto exercises = loadManifest(kLessons.parent_path() / "exercises/manifest.tsv");
    std::set<std::string> opened;
    for (const Lesson& lesson : loadLessons(kLessons))
        for (const std::string& name : lesson.codeExercises) {
            EXPECT_NE(findExercise(exercises, name), nullptr) << lesson.file << " opens " << name << ", which is no exercise";
            opened.insert(name);
        }
    for (const Exercise& e : exercises) EXPECT_TRUE(opened.count(e.name)) << e.name << " is in no lesson's Write it yourself";
}

// The notebooks (notebooks/*.ipynb) are where a lesson's "Going further" sends a student: every
// notebook a lesson names exists, and every notebook is named by some lesson.
TEST(Lessons, GoingFurtherPointsToEveryNotebook) {
    const fs::path root = kLessons.parent_path();
    std::set<std::string> notebooks;
    for (const auto& entry : fs::directory_iterator(root / "notebooks"))
        if (entry.path().extension() == ".ipynb") notebooks.insert("notebooks/" + entry.path().filename().string());
    ASSERT_GE(notebooks.size(), 4u);
    std::set<std::string> named;
    for (const Lesson& lesson : loadLessons(kLessons)) {
        const std::string& text = lesson.goingFurther;
        for (size_t at = text.find("notebooks/"); at != std::string::npos; at = text.find("notebooks/", at + 1)) {
            const size_t end = text.find(".ipynb", at);
            ASSERT_NE(end, std::string::npos) << lesson.file << ": 'notebooks/' without a notebook file";
            const std::string path = text.substr(at, end + 6 - at);
            EXPECT_TRUE(notebooks.count(path)) << lesson.file << " names " << path << ", which does not exist";
            named.insert(path);
        }
    }
    for (const std::string& n : notebooks) EXPECT_TRUE(named.count(n)) << n << " is in no lesson's Going further";
}

TEST_P(ShippedLesson, LoadsWithItsSceneAndEveryStepApplies) {
    const Lesson lesson = loadLesson(kLessons / GetParam());
    EXPECT_FALSE(lesson.title.empty());
    EXPECT_GE(lesson.goals.size(), 2u);
    EXPECT_GE(lesson.steps.size(), 3u);
    EXPECT_LE(lesson.steps.size(), 6u);
    EXPECT_GE(lesson.questions.size(), 3u);
    EXPECT_FALSE(lesson.exercise.empty());
    EXPECT_FALSE(lesson.sources.empty()) << "a lesson cites its sources";
    EXPECT_EQ(loadError(lesson.scenePath, {}), "");
    // A teacher sees whom the lesson is for, how long it takes, and which steps a short class keeps.
    EXPECT_FALSE(lesson.level.empty()) << GetParam() << ": no 'Level:' line";
    EXPECT_GT(lesson.minutes, 0) << GetParam() << ": no 'Minutes:' line";
    EXPECT_TRUE(std::any_of(lesson.steps.begin(), lesson.steps.end(), [](const LessonStep& s) { return !s.optional; }))
        << GetParam() << ": every step is optional";
    for (const LessonStep& step : lesson.steps) {
        EXPECT_FALSE(step.text.empty()) << GetParam() << ":" << step.line << ": step without text";
        // Steps can be taken in any order (presenter keys jump), so each starts by opening a scene.
        ASSERT_FALSE(step.commands.empty());
        EXPECT_EQ(step.commands.front().name, "open") << GetParam() << ":" << step.line;
    }
    std::set<int> used;
    checkSteps(lesson, used);
}

// A step shows the state its text describes: every sub-step (lesson.h: a block cut at `hold`)
// ends with `expect` lines, checked by checkSteps above, and changes nothing after it starts to
// wait for samples, so no comparison plays through to its last state unseen.
TEST_P(ShippedLesson, EverySubStepHoldsAnExpectedState) {
    const Lesson lesson = loadLesson(kLessons / GetParam());
    for (const LessonStep& step : lesson.steps) {
        std::vector<std::vector<ScriptCommand>> parts(1);
        for (const ScriptCommand& c : step.commands) {
            if (c.name == "hold") parts.emplace_back();
            else parts.back().push_back(c);
        }
        for (size_t p = 0; p < parts.size(); ++p) {
            const std::string at = GetParam() + ":" + std::to_string(step.line) + ": step " + step.title + ", part " +
                                   std::to_string(p + 1);
            ASSERT_FALSE(parts[p].empty()) << at;
            EXPECT_EQ(parts[p].back().name, "expect") << at << ": a sub-step ends with the state it shows";
            bool waited = false;
            for (const ScriptCommand& c : parts[p]) {
                const bool wait = c.name == "wait-spp" || c.name == "wait-frames";
                EXPECT_FALSE(waited && !wait && c.name != "expect")
                    << at << ": line " << c.line << ": " << c.name << " after a wait plays through a comparison; "
                    << "put a hold before it";
                waited = waited || wait;
            }
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Lessons, ShippedLesson, testing::ValuesIn(lessonFileNames()), testName);

// Every entry of kNeedsOtherBranches is used by the lesson it names (no stale entries).
TEST(Lessons, AllowListHasNoStaleEntries) {
    std::set<int> used;
    for (const Lesson& lesson : loadLessons(kLessons)) checkSteps(lesson, used);
    for (size_t i = 0; i < kNeedsOtherBranches.size(); ++i)
        EXPECT_TRUE(used.count(int(i))) << kNeedsOtherBranches[i].lesson << " does not use "
                                        << kNeedsOtherBranches[i].what << " (listed for "
                                        << kNeedsOtherBranches[i].branch << ")";
}

TEST(Lessons, AllowListPatternsMatchWholeParts) {
    EXPECT_TRUE(keyMatches("materials.*.roughness", "materials.ball.roughness"));
    EXPECT_FALSE(keyMatches("materials.*.roughness", "materials.ball.albedo"));
    EXPECT_FALSE(keyMatches("materials.*.roughness", "materials.roughness"));
    EXPECT_FALSE(keyMatches("render.nee", "render.nee.x"));
    EXPECT_TRUE(keyMatches("render.nee", "render.nee"));
}

// Claims of the lessons that a test can check: answer keys with numbers, computed here from the
// formula (or the scene) the lesson gives, and what the lessons say a scene holds.
namespace {

const fs::path kScenes = fs::path(RAYLAB_SOURCE_DIR) / "scenes";

Lesson lessonNamed(const std::string& file) { return loadLesson(kLessons / file); }

// `value` written with `decimals` digits after the point, as a lesson writes it ("0.41", "-0.42").
std::string fixed(double value, int decimals) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(decimals);
    s << value;
    return s.str();
}

const Material& materialNamed(const Scene& scene, const std::string& name) {
    for (const Material& m : scene.materials)
        if (m.name == name) return m;
    throw std::runtime_error("no material " + name);
}

// Runs of spaces and line breaks count as one space, so rewrapping a paragraph keeps a claim found.
std::string flat(const std::string& text) {
    std::string out;
    for (char ch : text) {
        const bool space = ch == ' ' || ch == '\n' || ch == '\t';
        if (!space) out += ch;
        else if (!out.empty() && out.back() != ' ') out += ' ';
    }
    return out;
}

bool contains(const std::string& text, const std::string& part) { return flat(text).find(flat(part)) != std::string::npos; }

} // namespace

// Lesson 2 says, where "rpp" first appears, that the thesis's rpp is raylab's render.spp.
TEST(LessonClaims, RppIsAlignedWithTheThesisWhereItFirstAppears) {
    const std::vector<Lesson> lessons = loadLessons(kLessons);
    const auto first = std::find_if(lessons.begin(), lessons.end(), [](const Lesson& l) {
        return contains(l.introduction, "rpp") || std::any_of(l.steps.begin(), l.steps.end(), [](const LessonStep& s) {
                   return contains(s.text, "rpp");
               });
    });
    ASSERT_NE(first, lessons.end());
    EXPECT_EQ(first->file.filename(), "02-monte-carlo.md");
    EXPECT_TRUE(contains(first->introduction, "The thesis's \"rpp\""));
    EXPECT_TRUE(contains(first->introduction, "raylab calls `render.spp`"));
}

// Lesson 6: the closed furnace's numbers follow from its scene (Le = emission × strength, albedo a).
TEST(LessonClaims, ClosedFurnaceSeriesMatchesItsScene) {
    const Lesson l = lessonNamed("06-emission-throughput.md");
    const Scene scene = loadScene(kScenes / "closed_furnace.json");
    const Material& glow = materialNamed(scene, "glow");
    const double le = glow.radiance().x, a = glow.albedo.x;
    EXPECT_TRUE(contains(l.steps[0].text, "Le = " + fixed(le, 1)));
    EXPECT_TRUE(contains(l.steps[0].text, "= " + fixed(le / (1 - a), 1)));
    // Step 2: L = Le (1 − a^(k+1))/(1 − a) for k = 0..3.
    std::string truncated;
    for (int k = 0; k <= 3; ++k) {
        const double v = le * (1 - std::pow(a, k + 1)) / (1 - a);
        EXPECT_TRUE(contains(l.steps[1].text, fixed(v, k + 1))) << "k = " << k << ": " << fixed(v, k + 1);
    }
    // Q2 (albedo 0.9) and the exercise (strength 0.2, albedo 0.75).
    EXPECT_TRUE(contains(l.teacherNotes, "0.5/(1 − 0.9) = 5"));
    const int k = int(std::ceil(std::log(0.01) / std::log(0.9))) - 1;   // smallest k with 0.9^(k+1) < 0.01
    EXPECT_TRUE(contains(l.teacherNotes, "k ≥ " + std::to_string(k)));
    EXPECT_TRUE(contains(l.teacherNotes, "that is " + fixed(0.2 / (1 - 0.75), 1)));
    // Roulette: the rule the lesson gives is the tracer's (russian_roulette.glsl), the fourth root
    // of max(β) under pbrt-v3's cap; pbrt-v4 has no cap.
    EXPECT_TRUE(contains(l.steps[3].text, "raylab takes q = min(max(β)^(1/4), 0.95)"));
    EXPECT_FLOAT_EQ(glsl::rouletteProbability(glsl::vec3(0.0625f, 0.01f, 0.0f)), 0.5f);
    EXPECT_FLOAT_EQ(glsl::rouletteProbability(glsl::vec3(0.99f)), 0.95f);
    EXPECT_TRUE(contains(l.steps[3].text, "pbrt-v3 takes q = min(max(β), 0.95)"));
    EXPECT_FALSE(contains(l.steps[3].text, "as pbrt-v4 does"));
    EXPECT_FALSE(contains(l.steps[2].text, "caps albedo"));
}

// Lesson 7, Q3: a concave Lambertian bowl under a sky of 1 reads ρ(1 − F)/(1 − ρF), less than ρ.
TEST(LessonClaims, BowlAnswerIsLessThanTheAlbedo) {
    const Lesson l = lessonNamed("07-lambert.md");
    const double rho = 0.5, f = 0.5;
    const double bowl = rho * (1 - f) / (1 - rho * f);
    EXPECT_LT(bowl, rho);
    EXPECT_TRUE(contains(l.teacherNotes, "For ρ = 0.5 and F = 0.5 a pixel reads " + fixed(bowl, 3)));
    EXPECT_TRUE(contains(l.teacherNotes, "*less* than ρ"));
    EXPECT_FALSE(contains(l.teacherNotes, "more than ρ"));
    // The furnace sphere's material of step 1 is the scene's, at the albedo the step names.
    EXPECT_FLOAT_EQ(materialNamed(loadScene(kScenes / "furnace.json"), "grey").albedo.x, 0.5f);
}

// Lesson 8 names only materials that scenes/materials.json has, and its Schlick answers are right.
TEST(LessonClaims, MaterialsRowAndSchlickAnswers) {
    const Lesson l = lessonNamed("08-microfacets-ggx-fresnel.md");
    const Scene row = loadScene(kScenes / "materials.json");
    std::string names;
    for (const Material& m : row.materials) names += m.name + " ";
    for (const char* metal : {"gold", "silver", "copper", "aluminium", "iron", "chrome", "brass"}) {
        const bool named = contains(l.steps[4].text, metal);
        EXPECT_EQ(named, contains(names, metal)) << metal << (named ? " is named but not in" : " is in but not named in")
                                                 << " materials.json (" << names << ")";
    }
    for (const char* kind : {"plastic", "mirror", "glass"})
        EXPECT_TRUE(contains(l.steps[4].text, kind) && contains(names, kind)) << kind;
    // The polar plot of (ρ/π) cos θ is a full circle, not a half one.
    EXPECT_FALSE(contains(l.steps[5].text, "half circle"));
    EXPECT_TRUE(contains(l.steps[5].text, "full circle"));
    std::string schlick;
    for (double deg : {0.0, 60.0, 80.0, 89.0}) {
        const double c = std::cos(glm::radians(deg));
        schlick += (schlick.empty() ? "" : deg == 89.0 ? " and " : ", ") + fixed(0.04 + 0.96 * std::pow(1 - c, 5), 2);
    }
    EXPECT_TRUE(contains(l.teacherNotes, "Schlick gives " + schlick)) << schlick;
}

// Lesson 9: the lamps of each comparison have equal power (strength × r², the same emission).
TEST(LessonClaims, LampsOfEqualPower) {
    for (const char* file : {"lesson_lights.json", "veach_mis.json"}) {
        const Scene s = loadScene(kScenes / file);
        std::vector<double> power;
        for (const Sphere& sp : s.spheres) {
            const Material& m = s.materials.at(std::size_t(sp.material));
            if (m.emissionStrength > 0) power.push_back(m.emissionStrength * sp.radius * sp.radius);
        }
        ASSERT_GE(power.size(), 2u) << file;
        for (double p : power) EXPECT_NEAR(p / power[0], 1.0, 0.01) << file;
    }
    const Lesson l = lessonNamed("09-importance-sampling-nee-mis.md");
    EXPECT_TRUE(contains(l.steps[3].text, "(1/nf) Σ wf(Xi) f(Xi)/pf(Xi) + (1/ng) Σ wg(Yj) f(Yj)/pg(Yj)"));
}

// Lesson 10: the focus distances come from the default scene's camera and spheres.
TEST(LessonClaims, FocusDistancesFollowFromTheDefaultScene) {
    const Lesson l = lessonNamed("10-camera-depth-of-field.md");
    const Scene s = loadScene(kScenes / "default.json");
    const glm::vec3 w = glm::normalize(s.camera.lookAt - s.camera.position);
    auto depth = [&](const std::string& material) {
        for (const Sphere& sp : s.spheres)
            if (s.materials.at(std::size_t(sp.material)).name == material) return double(glm::dot(sp.center - s.camera.position, w));
        ADD_FAILURE() << "no " << material << " sphere";
        return 0.0;
    };
    const double yellow = depth("yellow"), green = depth("green");
    EXPECT_TRUE(contains(l.steps[2].text, fixed(yellow, 1) + " units")) << fixed(yellow, 1);
    EXPECT_TRUE(contains(l.steps[3].text, "(" + fixed(green, 1) + " units)")) << fixed(green, 1);
    auto focusOf = [](const LessonStep& step) {
        for (const ScriptCommand& c : step.commands)
            if (c.name == "set" && c.args[0] == "camera.focus_distance") return c.args[1];
        return std::string();
    };
    EXPECT_EQ(focusOf(l.steps[2]), fixed(yellow, 1));
    EXPECT_EQ(focusOf(l.steps[3]), fixed(green, 1));
    // The exercise: circle of confusion c = 2A|z − z_f|/z in pixels of the 32°, 360-pixel view.
    const double c = 2 * 0.15 * (green - yellow) / green;
    const double planeHeight = 2 * yellow * std::tan(glm::radians(double(s.camera.fovY)) / 2);
    EXPECT_EQ(s.render.height, 360);
    EXPECT_TRUE(contains(l.teacherNotes, "= " + fixed(c, 2) + " units"));
    EXPECT_TRUE(contains(l.teacherNotes, fixed(planeHeight, 2) + " units tall"));
    EXPECT_TRUE(contains(l.teacherNotes, "≈ " + std::to_string(int(std::lround(c / planeHeight * 360))) + " pixels"));
}

// Lesson 11's exercise and lesson 12's Fresnel exercise, computed.
TEST(LessonClaims, TextureAndFresnelAnswers) {
    const Lesson tex = lessonNamed("11-textures-level-of-detail.md");
    const double angle = 2 * std::tan(glm::radians(20.0)) / 720;
    const double near = angle * 10 * 1024 / 4, far = angle * 40 * 1024 / 4;
    EXPECT_TRUE(contains(tex.teacherNotes, fixed(near, 1) + " texels"));
    EXPECT_TRUE(contains(tex.teacherNotes, "λ = log2(" + fixed(near, 1) + ") ≈ " + fixed(std::log2(near), 1)));
    EXPECT_TRUE(contains(tex.teacherNotes, fixed(far, 1) + " texels"));
    EXPECT_TRUE(contains(tex.teacherNotes, "λ ≈ " + fixed(std::log2(far), 1)));
    EXPECT_TRUE(contains(tex.goals[0], "frequencies above half the sampling rate"));
    // Step 3 shows trilinear filtering on an image texture.
    EXPECT_EQ(tex.steps[2].commands.front().args.at(0), "scenes/textured_bricks.json");

    const Lesson glass = lessonNamed("12-glass-refraction.md");
    const double ci = std::cos(glm::radians(60.0)), eta = 1.5;
    const double st = std::sin(glm::radians(60.0)) / eta, ct = std::sqrt(1 - st * st);
    const double rs = (ci - eta * ct) / (ci + eta * ct), rp = (eta * ci - ct) / (eta * ci + ct);
    const double f = (rs * rs + rp * rp) / 2;
    EXPECT_TRUE(contains(glass.teacherNotes, "= " + fixed(glm::degrees(std::asin(st)), 1) + "°"));
    EXPECT_TRUE(contains(glass.teacherNotes, "r_s = " + fixed(rs, 2).replace(0, 1, "−")));
    EXPECT_TRUE(contains(glass.teacherNotes, "r_p = " + fixed(rp, 2).replace(0, 1, "−")));
    EXPECT_TRUE(contains(glass.teacherNotes, "≈ " + fixed(f, 2)));
    EXPECT_TRUE(contains(glass.teacherNotes, std::to_string(int(std::lround(100 * (1 - f)))) + "% is transmitted"));
}

// Lesson 3's exercise hits the ball of its scene; lesson 5's scenes need no top-level tree.
TEST(LessonClaims, SphereExerciseAndObjectCounts) {
    const Lesson l3 = lessonNamed("03-ray-sphere.md");
    const Scene one = loadScene(kScenes / "lesson_one_sphere.json");
    const Sphere& ball = one.spheres.at(1);
    EXPECT_EQ(ball.center, glm::vec3(0, 1, 0));
    EXPECT_EQ(ball.radius, 1.0f);
    // o = (0, 1, 5), d = (0, 0, −1): t = 5 ∓ R.
    EXPECT_TRUE(contains(l3.teacherNotes, "t = " + std::to_string(int(5 - ball.radius)) + " and " +
                                              std::to_string(int(5 + ball.radius))));

    const Lesson l5 = lessonNamed("05-ray-box-bvh.md");
    const Scene terrain = loadScene(kScenes / "displaced_terrain.json");
    const std::size_t objects = terrain.spheres.size() + terrain.meshes.size();
    EXPECT_EQ(objects, 3u);
    EXPECT_LE(objects, kLinearTopLevelMax);
    EXPECT_TRUE(contains(l5.steps[2].text, "three objects"));
    EXPECT_TRUE(contains(l5.steps[2].text, "up to " + std::to_string(kLinearTopLevelMax) + " objects"));
    EXPECT_FALSE(contains(l5.steps[2].text, "BVH over the objects"));
    EXPECT_EQ(loadScene(kScenes / "default.json").spheres.size(), 8u);   // "eight spheres", step 4
    EXPECT_TRUE(contains(l5.steps[3].text, "up to " + std::to_string(kLinearTopLevelMax) + " objects"));
    std::size_t triangles = 0;
    for (const Mesh& m : terrain.meshes) triangles += m.triangles.size();
    EXPECT_EQ(triangles, 8192u);
}

// Lessons 13–18: the answer keys' numbers, computed from the formulas the lessons give (the tone
// curves from raylab's own shared header).
TEST(LessonClaims, NewLessonsAnswerKeys) {
    const double kPi = std::acos(-1.0);
    const Lesson acc = lessonNamed("13-accumulation.md");
    EXPECT_TRUE(contains(acc.teacherNotes, "1024/16 = " + std::to_string(1024 / 16) + " passes"));
    EXPECT_EQ(float(1 << 24) + 1.0f, float(1 << 24));   // where a float32 sum of ones stops
    EXPECT_TRUE(contains(acc.teacherNotes, "at 2^24 = 16 777 216"));
    EXPECT_TRUE(contains(acc.teacherNotes, "64/65 ≈ " + fixed(64.0 / 65.0, 3)));
    EXPECT_TRUE(contains(acc.steps[1].text, std::to_string(int(std::lround(64.0 * 3 * 640 * 360 * 4 / 1e6))) + " MB"));

    const Lesson sky = lessonNamed("14-sky-environment-light.md");
    const double texel = (2 * kPi / 512) * (kPi / 256);
    EXPECT_TRUE(contains(sky.teacherNotes, fixed(texel * 1e4, 2) + " × 10⁻⁴ sr"));
    EXPECT_TRUE(contains(sky.teacherNotes, std::to_string(int(std::lround(1 / std::sin(kPi / 512)))) + " times less"));
    const double sunSolidAngle = 2 * kPi * (1 - std::cos(glm::radians(5.0)));
    EXPECT_TRUE(contains(sky.steps[2].text, fixed(sunSolidAngle, 3) + " sr"));
    EXPECT_TRUE(contains(sky.teacherNotes, "≈ " + fixed(sunSolidAngle * std::sin(glm::radians(35.0)) / kPi, 4)));
    EXPECT_TRUE(contains(sky.teacherNotes, "π·65/16 ≈ " + fixed(kPi * 65 / 16, 2)));

    const Lesson ggx = lessonNamed("15-ggx-importance-sampling.md");
    EXPECT_TRUE(contains(ggx.teacherNotes, "1 − ln 2 ≈ " + fixed(1 - std::log(2.0), 3)));
    EXPECT_TRUE(contains(ggx.teacherNotes, "up to " + std::to_string(int(std::lround(100 * std::log(2.0)))) + "%"));

    const Lesson tone = lessonNamed("16-rgb-exposure-tone-mapping.md");
    std::string reinhard, aces;
    for (float x : {0.18f, 1.0f, 4.0f}) {
        reinhard += (reinhard.empty() ? "" : ", ") + fixed(glsl::toneReinhard(x), x == 0.18f ? 3 : 1);
        aces += (aces.empty() ? "" : ", ") + fixed(glsl::toneAcesFit(x), 3);
    }
    EXPECT_TRUE(contains(tone.teacherNotes, "Reinhard " + reinhard)) << reinhard;
    EXPECT_TRUE(contains(tone.teacherNotes, "ACES fit " + aces)) << aces;
    EXPECT_LT(glsl::toneAcesFit(7.2f), 1.0f);
    EXPECT_EQ(glsl::toneAcesFit(7.3f), 1.0f);   // "reaches 1 at x ≈ 7.24"
    EXPECT_TRUE(contains(tone.teacherNotes, "≈ " + fixed(std::pow((0.5 + 0.055) / 1.055, 2.4), 3) + " of the light"));
    EXPECT_TRUE(contains(tone.steps[1].text, "stored as " + fixed(glsl::srgbEncode(0.18f), 2)));
    EXPECT_TRUE(contains(tone.teacherNotes, "log2(54.6) ≈ " + fixed(std::log2(60 * (0.2126 + 0.7152 * 0.9 + 0.0722 * 0.75)), 1)));
    std::string angles;
    for (double n : {1.5143, 1.5224})
        angles += (angles.empty() ? "" : "° for red and ") + fixed(glm::degrees(std::asin(std::sin(glm::radians(45.0)) / n)), 2);
    EXPECT_TRUE(contains(tone.teacherNotes, angles + "° for blue")) << angles;

    const Lesson err = lessonNamed("18-find-the-error.md");
    auto schlick = [](double c) { return 0.04 + 0.96 * std::pow(1 - std::max(c, 0.0), 5); };
    std::string right, wrong;
    for (double deg : {30.0, 45.0, 60.0}) {
        right += (right.empty() ? "" : ", ") + fixed(schlick(std::cos(glm::radians(deg))), 4);
        wrong += (wrong.empty() ? "" : ", ") + fixed(schlick(std::cos(glm::radians(2 * deg))), 4);
    }
    EXPECT_TRUE(contains(err.teacherNotes, "With ωi·h: " + right)) << right;
    EXPECT_TRUE(contains(err.teacherNotes, "0): " + wrong)) << wrong;
    EXPECT_TRUE(contains(err.teacherNotes, "= " + fixed(0.3 / (4 * 0.5), 2) + " at 16"));
    EXPECT_TRUE(contains(err.teacherNotes, "= " + fixed(0.3 / (16 * 0.5), 4) + " at 256"));
}
