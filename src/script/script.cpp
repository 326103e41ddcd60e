#include "script/script.h"

#include "render/debug_views.h"
#include "script/key_actions.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

namespace raylab {
namespace {

struct Arity {
    int min;
    int max;
};

const std::map<std::string, Arity, std::less<>>& commands() {
    static const std::map<std::string, Arity, std::less<>> table = {
        {"open", {1, 1}},        {"set", {2, 2}},         {"click", {2, 2}},      {"pick", {2, 2}},
        {"select", {1, 1}},      {"debug-view", {1, 1}},  {"overlay", {2, 2}},    {"scale", {1, 1}},
        {"pause", {0, 0}},       {"resume", {0, 0}},      {"reset", {0, 0}},      {"wait-spp", {1, 1}},
        {"wait-frames", {1, 1}}, {"screenshot", {1, 1}},  {"export", {1, 1}},     {"save", {1, 1}},
        {"window", {2, 2}},      {"quit", {0, 0}},        {"debug-bounce", {1, 1}},
        {"inspect", {2, 3}},     {"inspect-export", {1, 1}}, {"explore", {1, 2}},  {"panel", {2, 2}},
        {"focus", {2, 2}},       {"focus-mode", {1, 1}},  {"bvh-depth", {1, 1}},  {"heat-scale", {1, 1}},
        {"bounce-step", {1, 1}}, {"stage", {1, 1}},       {"split", {1, 1}},      {"split-a", {2, 2}},
        {"split-b", {2, 2}},     {"split-divider", {1, 1}}, {"ui-scale", {1, 1}}, {"key", {1, 2}},
        {"lesson", {1, 1}},      {"lesson-step", {1, 1}}, {"self-test", {0, 0}},   {"teach", {1, 1}},
        {"drop", {1, 1}},        {"expect", {2, 2}},      {"hold", {0, 0}},       {"select-light", {1, 1}},
    };
    return table;
}

// The `name` of each of a table's first N rows, in its order.
template <std::size_t N, typename Row>
constexpr std::array<std::string_view, N> namesOf(const Row* rows) {
    std::array<std::string_view, N> names{};
    for (std::size_t i = 0; i < N; ++i) names[i] = rows[i].name;
    return names;
}

// The debug views by name, in table order (shaders/include/debug_view_table.glsl).
constexpr auto kDebugViewNames = namesOf<std::size(kDebugViewTable)>(kDebugViewTable);

std::string debugViewList() {
    std::string list;
    for (std::string_view name : kDebugViewNames) list += (list.empty() ? "" : ", ") + std::string(name);
    return list;
}

// The names `key` presses: the key actions, then the camera keys, in the tables' order.
constexpr auto kKeys = [] {
    const auto actions = namesOf<kKeyBindings.size()>(kKeyBindings.data());
    const auto camera = namesOf<kCameraKeys.size()>(kCameraKeys.data());
    std::array<std::string_view, actions.size() + camera.size()> all{};
    std::copy(actions.begin(), actions.end(), all.begin());
    std::copy(camera.begin(), camera.end(), all.begin() + actions.size());
    return all;
}();

std::string keyChoices() {
    std::string text;
    for (std::size_t i = 0; i < kKeys.size(); ++i)
        text += (i == 0 ? "" : i + 1 == kKeys.size() ? " or " : ", ") + std::string(kKeys[i]);
    return text;
}

// render.stage's names (scene/parameters.cpp; tests/script keeps the two in step).
constexpr std::array<std::string_view, 6> kStages = {"primary", "emission", "lambert", "ggx", "textures", "full"};

bool isNumber(const std::string& s) {
    double v = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && p == s.data() + s.size();
}

} // namespace

std::span<const std::string_view> scriptDebugViews() { return kDebugViewNames; }
std::span<const std::string_view> scriptKeys() { return kKeys; }

std::string ScriptCommand::text() const {
    std::string t = "line " + std::to_string(line) + ": " + name;
    for (const std::string& a : args) t += " " + a;
    return t;
}

std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& fileName, int firstLine) {
    std::vector<ScriptCommand> out;
    std::istringstream in(text);
    std::string raw;
    int lineNo = firstLine - 1;
    while (std::getline(in, raw)) {
        ++lineNo;
        std::string line = raw.substr(0, raw.find('#'));
        auto fail = [&](const std::string& what) {
            throw ScriptError(fileName + ":" + std::to_string(lineNo) + ": error: " + what);
        };
        std::istringstream words(line);
        ScriptCommand c;
        c.line = lineNo;
        if (!(words >> c.name)) continue;
        const auto it = commands().find(c.name);
        if (it == commands().end()) fail("unknown command '" + c.name + "'");
        if (c.name == "set" || c.name == "split-a" || c.name == "split-b" || c.name == "expect") {
            std::string key, rest;
            words >> key;
            std::getline(words, rest);
            const auto first = rest.find_first_not_of(" \t");
            if (key.empty() || first == std::string::npos) fail(c.name + " needs KEY VALUE");
            c.args = {key, rest.substr(first, rest.find_last_not_of(" \t\r") - first + 1)};
        } else {
            for (std::string w; words >> w;) c.args.push_back(w);
        }
        const int n = int(c.args.size());
        if (n < it->second.min || n > it->second.max)
            fail(c.name + " takes " + std::to_string(it->second.min) +
                 (it->second.max > it->second.min ? " or " + std::to_string(it->second.max) : "") + " argument(s), got " +
                 std::to_string(n));
        const bool numeric = c.name == "click" || c.name == "pick" || c.name == "select" || c.name == "select-light" ||
                             c.name == "scale" ||
                             c.name == "wait-spp" || c.name == "wait-frames" || c.name == "window" ||
                             c.name == "debug-bounce" || c.name == "inspect" || c.name == "explore" ||
                             c.name == "focus" || c.name == "bvh-depth" || c.name == "split-divider" ||
                             c.name == "ui-scale" || c.name == "lesson-step";
        if (numeric)
            for (const std::string& a : c.args)
                if (!isNumber(a)) fail(c.name + ": '" + a + "' is not a number");
        if (c.name == "debug-view" && !parseDebugView(c.args[0]))
            fail("unknown debug view '" + c.args[0] + "' (" + debugViewList() + ")");
        if ((c.name == "split-a" || c.name == "split-b") && c.args[0] == "debug-view" && !parseDebugView(c.args[1]))
            fail("unknown debug view '" + c.args[1] + "' (" + debugViewList() + ")");
        const auto onOff = [](const std::string& w) { return w == "on" || w == "off"; };
        if (c.name == "overlay" && ((c.args[0] != "boxes" && c.args[0] != "selected" && c.args[0] != "paths" &&
                                     c.args[0] != "bvh" && c.args[0] != "mesh-bvh" && c.args[0] != "lights") ||
                                    !onOff(c.args[1])))
            fail("overlay takes boxes|selected|paths|bvh|mesh-bvh|lights on|off");
        if (c.name == "panel" && ((c.args[0] != "inspector" && c.args[0] != "brdf-explorer") || !onOff(c.args[1])))
            fail("panel takes inspector|brdf-explorer on|off");
        if (c.name == "focus-mode" && !onOff(c.args[0])) fail("focus-mode takes on|off");
        if (c.name == "heat-scale" && c.args[0] != "auto" && (!isNumber(c.args[0]) || std::stod(c.args[0]) <= 0.0))
            fail("heat-scale takes auto or a count > 0");
        if (c.name == "bounce-step" && c.args[0] != "next" && c.args[0] != "off" && !isNumber(c.args[0]))
            fail("bounce-step takes a number, next or off");
        if (c.name == "stage" && std::find(kStages.begin(), kStages.end(), c.args[0]) == kStages.end())
            fail("unknown stage '" + c.args[0] + "' (primary, emission, lambert, ggx, textures, full)");
        if (c.name == "split" && c.args[0] != "samples" && c.args[0] != "time" && c.args[0] != "off")
            fail("split takes samples, time or off");
        if (c.name == "teach" && c.args[0] != "lesson" && c.args[0] != "classroom" && c.args[0] != "self-test" &&
            c.args[0] != "off")
            fail("teach takes lesson, classroom, self-test or off");
        if (c.name == "expect") {
            const std::string& what = c.args[0];
            if (what == "debug-view" && !parseDebugView(c.args[1]))
                fail("unknown debug view '" + c.args[1] + "' (" + debugViewList() + ")");
            if (what == "scale" && !isNumber(c.args[1])) fail("expect scale takes a number");
            if (what == "bounce-step" && c.args[1] != "off" && !isNumber(c.args[1]))
                fail("expect bounce-step takes a number or off");
        }
        if (c.name == "key" && std::find(kKeys.begin(), kKeys.end(), c.args[0]) == kKeys.end())
            fail("key takes " + keyChoices());
        if (c.name == "key" && n == 2 && (!isNumber(c.args[1]) || std::stod(c.args[1]) < 1.0 ||
                                          std::stod(c.args[1]) != std::floor(std::stod(c.args[1]))))
            fail("key: '" + c.args[1] + "' is not a count of frames (a whole number >= 1)");
        out.push_back(std::move(c));
    }
    return out;
}

std::vector<ScriptCommand> loadScript(const std::filesystem::path& file) {
    std::ifstream in(file);
    if (!in) throw ScriptError(file.string() + ": error: cannot open the script");
    std::stringstream s;
    s << in.rdbuf();
    return parseScript(s.str(), file.string());
}

} // namespace raylab
