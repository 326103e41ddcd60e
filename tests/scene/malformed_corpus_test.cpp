// Every file of tests/data/malformed/ (written by tests/data/make_malformed.py) ends in a located
// SceneError that says what is wrong: meshes and images loaded through a scene that names them,
// json_* files loaded as scenes (with the manifest's --set overrides). One case per line of
// expected.tsv, so a new file there is a new case here; malformed_corpus_cli_test.cpp runs the same
// manifest through raylab-render.
#include "scene/parameters.h"
#include "scene/scene_loader.h"

#include "support/malformed_corpus.h"

#include <algorithm>
#include <set>
#include <unistd.h>

using namespace raylab::test;

namespace {

class MalformedCorpus : public testing::TestWithParam<CorpusEntry> {};

} // namespace

TEST(MalformedCorpusManifest, ListsEnoughFilesThatExist) {
    const std::vector<CorpusEntry> entries = corpusManifest();
    EXPECT_GE(entries.size(), 150u);
    for (const CorpusEntry& e : entries) {
        EXPECT_TRUE(fs::is_regular_file(kCorpus / e.file)) << e.file;
        EXPECT_FALSE(e.expected.empty()) << e.file << " has no expected message";
        EXPECT_TRUE(e.overrides.empty() || isSceneCase(e)) << e.file << ": only json_* cases take --set";
    }
}

// make_malformed.py writes json_type_<type>_* cases for each key type of the table: a new type
// fails here until the script covers it.
TEST(MalformedCorpusManifest, CoversEveryKeyTypeOfTheParameterTable) {
    std::set<std::string> types;
    for (const auto& p : raylab::sceneParameters()) types.insert(std::string(raylab::typeName(p.type)));
    for (const auto& p : raylab::materialParameters()) types.insert(std::string(raylab::typeName(p.type)));
    for (const auto& p : raylab::sphereParameters()) types.insert(std::string(raylab::typeName(p.type)));
    for (const auto& p : raylab::transformParameters()) types.insert(std::string(raylab::typeName(p.type)));
    EXPECT_GE(types.size(), 7u);
    const std::vector<CorpusEntry> entries = corpusManifest();
    for (const std::string& type : types) {
        const std::string prefix = "json_type_" + type + "_";
        std::size_t n = 0;
        for (const CorpusEntry& e : entries) n += e.file.rfind(prefix, 0) == 0;
        EXPECT_GE(n, 2u) << "no malformed cases for key type " << type << " (" << prefix << "*)";
    }
    for (const char* key : {"sky.map", "albedo_texture", "file", "positions", "indices"}) {
        std::string slug = key;
        std::replace(slug.begin(), slug.end(), '.', '_');
        std::size_t n = 0;
        for (const CorpusEntry& e : entries) n += e.file.rfind("json_key_" + slug + "_", 0) == 0;
        EXPECT_GE(n, 1u) << "no malformed case for the file or array key " << key;
    }
}

TEST_P(MalformedCorpus, GivesALocatedErrorNamingTheFile) {
    const CorpusEntry& entry = GetParam();
    const CorpusScene s = corpusScene(entry, fs::temp_directory_path() / ("raylab_corpus_" + std::to_string(::getpid())));
    std::string message;
    try {
        raylab::loadScene(s.scene, entry.overrides);
        FAIL() << entry.file << " loaded without an error";
    } catch (const raylab::SceneError& e) {
        message = e.what();
    } catch (const std::exception& e) {
        FAIL() << entry.file << ": not a SceneError: " << e.what();
    }
    expectCorpusMessage(entry, s, message);
}

INSTANTIATE_TEST_SUITE_P(Files, MalformedCorpus, testing::ValuesIn(corpusManifest()), corpusTestName);
