// Every file of tests/data/malformed/ (written by tests/data/make_malformed.py), loaded through a
// scene that refers to it, ends in a located SceneError that names the file and says what is
// wrong: one case per line of expected.tsv, so a new file there is a new case here.
#include "scene/scene_loader.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <unistd.h>

namespace fs = std::filesystem;

namespace {

struct CorpusEntry {
    std::string file;       // in tests/data/malformed/
    std::string expected;   // a piece of the message
};

const fs::path kCorpus = fs::path(RAYLAB_SOURCE_DIR) / "tests" / "data" / "malformed";

std::vector<CorpusEntry> manifest() {
    std::vector<CorpusEntry> entries;
    std::ifstream in(kCorpus / "expected.tsv");
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        const std::size_t tab = line.find('\t');
        entries.push_back({line.substr(0, tab), tab == std::string::npos ? "" : line.substr(tab + 1)});
    }
    return entries;
}

bool isMesh(const fs::path& file) {
    const std::string ext = file.extension().string();
    return ext == ".obj" || ext == ".gltf" || ext == ".glb";
}

class MalformedCorpus : public testing::TestWithParam<CorpusEntry> {};

} // namespace

TEST(MalformedCorpusManifest, ListsEnoughFilesThatExist) {
    const std::vector<CorpusEntry> entries = manifest();
    EXPECT_GE(entries.size(), 100u);
    for (const CorpusEntry& e : entries) {
        EXPECT_TRUE(fs::is_regular_file(kCorpus / e.file)) << e.file;
        EXPECT_FALSE(e.expected.empty()) << e.file << " has no expected message";
    }
}

TEST_P(MalformedCorpus, GivesALocatedErrorNamingTheFile) {
    const CorpusEntry& entry = GetParam();
    const fs::path file = kCorpus / entry.file;
    const fs::path dir = fs::temp_directory_path() / ("raylab_corpus_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path scene = dir / "scene.json";
    nlohmann::json j;
    std::string key;
    if (isMesh(file)) {
        j["objects"] = nlohmann::json::array({{{"type", "mesh"}, {"file", file.string()}}});
        key = "objects[0].file";
    } else {
        j["materials"]["m"]["albedo_texture"] = file.string();
        j["objects"] = nlohmann::json::array({{{"type", "sphere"}, {"material", "m"}}});
        key = "materials.m.albedo_texture";
    }
    std::ofstream(scene) << j.dump();
    std::string message;
    try {
        raylab::loadScene(scene);
        FAIL() << entry.file << " loaded without an error";
    } catch (const raylab::SceneError& e) {
        message = e.what();
    } catch (const std::exception& e) {
        FAIL() << entry.file << ": not a SceneError: " << e.what();
    }
    EXPECT_EQ(message.rfind(scene.string() + ":1:", 0), 0u) << message;
    EXPECT_NE(message.find(": error: " + key + ": " + file.string() + ":"), std::string::npos) << message;
    EXPECT_NE(message.find(entry.expected), std::string::npos) << "expected '" << entry.expected << "' in\n" << message;
    for (const char* raw : {"std::", "vector::", "basic_string", "bad_alloc", "_M_", "json.exception"})
        EXPECT_EQ(message.find(raw), std::string::npos) << "raw exception text in\n" << message;
}

INSTANTIATE_TEST_SUITE_P(Files, MalformedCorpus, testing::ValuesIn(manifest()),
                         [](const testing::TestParamInfo<CorpusEntry>& entry) {
                             std::string name;
                             for (char c : entry.param.file) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                             return name;
                         });
