#pragma once
// tests/data/malformed/ (written by tests/data/make_malformed.py): its manifest, the scene that loads
// each file, and the check of the message. Shared by the in-process test and the raylab-render one.
#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace raylab::test {

namespace fs = std::filesystem;

struct CorpusEntry {
    std::string file;                    // in tests/data/malformed/
    std::string expected;                // pieces of the message, in order, "{...}" between them
    std::vector<std::string> overrides;  // --set strings, for json_* files
};

inline const fs::path kCorpus = fs::path(RAYLAB_SOURCE_DIR) / "tests" / "data" / "malformed";

inline std::vector<std::string> splitOn(const std::string& text, const std::string& separator) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t at; (at = text.find(separator, start)) != std::string::npos; start = at + separator.size())
        parts.push_back(text.substr(start, at - start));
    parts.push_back(text.substr(start));
    return parts;
}

inline std::vector<CorpusEntry> corpusManifest() {
    std::vector<CorpusEntry> entries;
    std::ifstream in(kCorpus / "expected.tsv");
    for (std::string line; std::getline(in, line);) {
        if (line.empty() || line[0] == '#') continue;
        const std::vector<std::string> cells = splitOn(line, "\t");
        CorpusEntry e{cells[0], cells.size() > 1 ? cells[1] : "", {}};
        if (cells.size() > 2 && !cells[2].empty()) e.overrides = splitOn(cells[2], "|");
        entries.push_back(e);
    }
    return entries;
}

// A json_* file is a scene itself; a mesh or an image is named by a scene written to `dir`.
inline bool isSceneCase(const CorpusEntry& e) { return e.file.rfind("json_", 0) == 0; }

// The scene that loads the entry, and for a mesh or image the key that names it.
struct CorpusScene {
    fs::path scene;
    std::string key;   // "" for json_* files
};

inline CorpusScene corpusScene(const CorpusEntry& e, const fs::path& dir) {
    const fs::path file = kCorpus / e.file;
    if (isSceneCase(e)) return {file, ""};
    const std::string ext = file.extension().string();
    nlohmann::json j;
    CorpusScene s{dir / "scene.json", ""};
    if (ext == ".obj" || ext == ".gltf" || ext == ".glb") {
        j["objects"] = nlohmann::json::array({{{"type", "mesh"}, {"file", file.string()}}});
        s.key = "objects[0].file";
    } else {
        j["materials"]["m"]["albedo_texture"] = file.string();
        j["objects"] = nlohmann::json::array({{{"type", "sphere"}, {"material", "m"}}});
        s.key = "materials.m.albedo_texture";
    }
    fs::create_directories(dir);
    std::ofstream(s.scene) << j.dump();
    return s;
}

// The message is located (scene file:line:column, or the --set that wrote the value), names the
// key and the mesh or image file, holds the expected pieces in order and no raw exception text.
inline void expectCorpusMessage(const CorpusEntry& e, const CorpusScene& s, const std::string& message) {
    const std::vector<std::string> pieces = splitOn(e.expected, "{...}");
    if (isSceneCase(e) && !e.overrides.empty()) {
        EXPECT_EQ(message.rfind("--set ", 0), 0u) << message;
    } else if (isSceneCase(e)) {
        const std::string head = s.scene.string() + ":";
        EXPECT_EQ(message.rfind(head, 0), 0u) << message;
        std::size_t line = 0, column = 0;
        const int read = std::sscanf(message.c_str() + std::min(head.size(), message.size()), "%zu:%zu: error: ", &line, &column);
        EXPECT_TRUE(read == 2 && line > 0 && column > 0) << "no line:column in\n" << message;
        if (pieces[0][0] == ':')
            EXPECT_EQ(message.rfind(s.scene.string() + pieces[0], 0), 0u)
                << "expected it to start with '" << s.scene.string() + pieces[0] << "':\n" << message;
    } else {
        EXPECT_EQ(message.rfind(s.scene.string() + ":1:", 0), 0u) << message;
        const std::string file = (kCorpus / e.file).string();
        EXPECT_NE(message.find(": error: " + s.key + ": " + file + ":"), std::string::npos) << message;
    }
    std::size_t at = 0;
    for (const std::string& piece : pieces) {
        const std::size_t found = message.find(piece, at);
        EXPECT_NE(found, std::string::npos) << "expected '" << piece << "' (after position " << at << ") in\n"
                                            << message;
        if (found != std::string::npos) at = found + piece.size();
    }
    for (const char* raw : {"std::", "vector::", "basic_string", "bad_alloc", "_M_", "json.exception"})
        EXPECT_EQ(message.find(raw), std::string::npos) << "raw exception text in\n" << message;
}

inline void PrintTo(const CorpusEntry& e, std::ostream* os) { *os << e.file; }

inline std::string corpusTestName(const testing::TestParamInfo<CorpusEntry>& entry) {
    std::string name;
    for (char c : entry.param.file) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return name;
}

} // namespace raylab::test
