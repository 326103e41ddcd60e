// scenes/FORMAT.md documents every key, and what it says matches the parameter table.
#include "scene/parameters.h"
#include "scene/scene_loader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace raylab;

namespace {

const std::filesystem::path kFormatDoc = std::filesystem::path(RAYLAB_SOURCE_DIR) / "scenes" / "FORMAT.md";

std::string readDoc() {
    std::ifstream in(kFormatDoc);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t");
    if (a == std::string::npos) return "";
    const auto b = s.find_last_not_of(" \t");
    return s.substr(a, b - a + 1);
}

// Table rows whose first cell is `key`: key -> cells (the first cell without backticks).
std::map<std::string, std::vector<std::string>> keyRows(const std::string& doc) {
    std::map<std::string, std::vector<std::string>> rows;
    std::istringstream lines(doc);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.empty() || line[0] != '|') continue;
        std::vector<std::string> cells;
        std::string cell;
        std::istringstream parts(line.substr(1));
        while (std::getline(parts, cell, '|')) cells.push_back(trim(cell));
        if (cells.empty() || cells[0].size() < 3 || cells[0].front() != '`' || cells[0].back() != '`') continue;
        const std::string key = cells[0].substr(1, cells[0].size() - 2);
        EXPECT_EQ(rows.count(key), 0u) << "documented twice: " << key;
        rows[key] = cells;
    }
    return rows;
}

// Checks a documented row against a table entry: type, unit, default, range, trigger columns.
void expectRowMatches(const std::map<std::string, std::vector<std::string>>& rows, const ValueSpec& spec,
                      const ParamValue& defaultValue) {
    const std::string key(spec.key);
    const auto it = rows.find(key);
    ASSERT_TRUE(it != rows.end()) << "`" << key << "` has no table row in " << kFormatDoc;
    const std::vector<std::string>& c = it->second;
    ASSERT_GE(c.size(), 7u) << key;
    EXPECT_EQ(c[1], typeName(spec.type)) << key << ": type column";
    EXPECT_EQ(c[2], spec.unit.empty() ? "-" : std::string(spec.unit)) << key << ": unit column";
    EXPECT_EQ(c[3], formatValue(spec, defaultValue)) << key << ": default column";
    EXPECT_EQ(c[4], describeRange(spec)) << key << ": range column";
    EXPECT_FALSE(c[5].empty()) << key << ": meaning column";
    EXPECT_EQ(c[6], triggerName(spec.trigger)) << key << ": change column";
}

} // namespace

TEST(SceneFormatDoc, EveryParameterKeyHasAMatchingTableRow) {
    const std::string doc = readDoc();
    ASSERT_FALSE(doc.empty()) << "cannot read " << kFormatDoc;
    const auto rows = keyRows(doc);
    for (const ParamSpec& p : sceneParameters()) expectRowMatches(rows, p, p.defaultValue());
}

TEST(SceneFormatDoc, EveryMaterialAndObjectKeyHasATableRow) {
    const auto rows = keyRows(readDoc());
    for (const MaterialParamSpec& p : materialParameters()) expectRowMatches(rows, p, p.defaultValue());
    for (const SphereParamSpec& p : sphereParameters()) expectRowMatches(rows, p, p.defaultValue());
    for (const TransformParamSpec& p : transformParameters()) expectRowMatches(rows, p, p.defaultValue());
    for (const LightParamSpec& p : lightParameters()) expectRowMatches(rows, p, p.defaultValue());
    for (const DisplacementParamSpec& p : displacementParameters()) expectRowMatches(rows, p, p.defaultValue());
    // Keys of an object that the loader handles itself.
    for (const char* key : {"type", "material", "sky.map"}) EXPECT_EQ(rows.count(key), 1u) << "`" << key << "` undocumented";
    for (std::string_view key : meshKeys()) EXPECT_EQ(rows.count(std::string(key)), 1u) << "`" << key << "` undocumented";
    for (std::string_view key : materialFileKeys()) EXPECT_EQ(rows.count(std::string(key)), 1u) << "`" << key << "` undocumented";
}

TEST(SceneFormatDoc, NoRowsForKeysThatDoNotExist) {
    const auto rows = keyRows(readDoc());
    for (const auto& [key, cells] : rows) {
        const bool known = findParameter(key) != nullptr || key == "type" || key == "material" || key == "sky.map" ||
                           std::any_of(materialParameters().begin(), materialParameters().end(),
                                       [&](const auto& p) { return p.key == key; }) ||
                           std::any_of(sphereParameters().begin(), sphereParameters().end(),
                                       [&](const auto& p) { return p.key == key; }) ||
                           std::any_of(transformParameters().begin(), transformParameters().end(),
                                       [&](const auto& p) { return p.key == key; }) ||
                           std::any_of(lightParameters().begin(), lightParameters().end(),
                                       [&](const auto& p) { return p.key == key; }) ||
                           std::any_of(displacementParameters().begin(), displacementParameters().end(),
                                       [&](const auto& p) { return p.key == key; }) ||
                           std::any_of(meshKeys().begin(), meshKeys().end(),
                                       [&](std::string_view k) { return k == key; }) ||
                           std::any_of(materialFileKeys().begin(), materialFileKeys().end(),
                                       [&](std::string_view k) { return k == key; });
        EXPECT_TRUE(known) << "FORMAT.md documents `" << key << "`, which the loader does not know";
    }
}

TEST(SceneFormatDoc, TheExampleParsesAndTheSetMessageIsReal) {
    const std::string doc = readDoc();
    // The first fenced block is a complete scene file (with comments).
    const auto open = doc.find("```jsonc\n");
    ASSERT_NE(open, std::string::npos);
    const auto start = open + 9;
    const auto close = doc.find("```", start);
    ASSERT_NE(close, std::string::npos);
    Scene s;
    ASSERT_NO_THROW(s = parseScene(doc.substr(start, close - start), "FORMAT.md example"));
    EXPECT_EQ(s.spheres.size(), 3u);
    // The documented --set error is what the loader says.
    std::string message;
    try {
        parseScene(R"({ "objects": [ {} ] })", "x.json", {"render.spp=abc"});
    } catch (const SceneError& e) {
        message = e.what();
    }
    ASSERT_FALSE(message.empty());
    EXPECT_NE(doc.find(message), std::string::npos) << "FORMAT.md should show: " << message;
}

TEST(SceneFormatDoc, EveryPathKeyIsDocumentedAsAPath) {
    const auto rows = keyRows(readDoc());
    for (const PathKey& p : pathKeys()) {
        const auto it = rows.find(std::string(p.key));
        ASSERT_TRUE(it != rows.end()) << "`" << p.key << "` undocumented";
        ASSERT_GE(it->second.size(), 3u) << p.key;
        EXPECT_EQ(it->second[2], "path") << p.key << ": unit column";
    }
}
