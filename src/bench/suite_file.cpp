#include "bench/suite_file.h"

#include "scene/json_locator.h"
#include "scene/json_parse.h"
#include "scene/scene_error.h"
#include "scene/scene_overrides.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <span>
#include <sstream>
#include <string_view>

namespace raylab {
using namespace scenefmt;

namespace {

constexpr std::string_view kModeKeys[] = {"width", "height", "max_spp", "seeds", "extend_spp", "reference_spp",
                                          "reference_batches", "peer_max_spp", "peer_extend_spp",
                                          "peer_decide_spp",
                                          "peer_reference_spp", "peer_timing_runs", "peer_thresholds"};
constexpr std::string_view kSceneKeys[] = {"name", "scene", "analytic", "peer", "variants"};
constexpr std::string_view kVariantKeys[] = {"name", "set"};

void requireObject(const Json& v, const JsonPath& p, std::span<const std::string_view> known) {
    if (!v.is_object()) fail(p, "expected an object { ... }, got " + typeOf(v));
    const std::vector<std::string_view> names(known.begin(), known.end());
    for (const auto& [key, value] : v.items())
        if (std::find(names.begin(), names.end(), key) == names.end()) failUnknownKey(p, key, names);
}

const Json& member(const Json& obj, const JsonPath& p, const char* key) {
    if (!obj.contains(key)) fail(p, std::string("missing key '") + key + "'");
    return obj.at(key);
}

// `atLeastName` names the key that sets the bound ("max_spp"), when it is not a constant.
int integer(const Json& obj, const JsonPath& p, const char* key, int atLeast, const char* atLeastName = nullptr) {
    const Json& v = member(obj, p, key);
    const JsonPath kp = p.key(key);
    if (!v.is_number()) fail(kp, "expected an integer, got " + typeOf(v));
    const double d = v.get<double>();
    if (d != std::floor(d) || std::abs(d) > std::numeric_limits<int>::max()) fail(kp, "expected an integer, got " + v.dump());
    if (d < atLeast)
        fail(kp, "must be at least " + (atLeastName ? std::string(atLeastName) + " (" + std::to_string(atLeast) + ")"
                                                    : std::to_string(atLeast)) +
                     ", got " + v.dump());
    return int(d);
}

int optionalInteger(const Json& obj, const JsonPath& p, const char* key, int fallback, int atLeast,
                    const char* atLeastName = nullptr) {
    return obj.contains(key) ? integer(obj, p, key, atLeast, atLeastName) : fallback;
}

bool boolean(const Json& obj, const JsonPath& p, const char* key, bool fallback) {
    if (!obj.contains(key)) return fallback;
    const Json& v = obj.at(key);
    if (!v.is_boolean()) fail(p.key(key), "expected true or false, got " + typeOf(v));
    return v.get<bool>();
}

std::string text(const Json& obj, const JsonPath& p, const char* key) {
    const Json& v = member(obj, p, key);
    if (!v.is_string() || v.get_ref<const std::string&>().empty())
        fail(p.key(key), "expected a non-empty string, got " + typeOf(v));
    return v.get<std::string>();
}

Suite build(const Json& doc, const std::string& modeName) {
    const JsonPath top;
    constexpr std::string_view kTopKeys[] = {"modes", "scenes"};
    requireObject(doc, top, kTopKeys);
    const Json& modes = member(doc, top, "modes");
    const JsonPath mp = top.key("modes");
    if (!modes.is_object()) fail(mp, "expected an object { ... }, got " + typeOf(modes));
    if (!modes.contains(modeName)) {
        std::vector<std::string> names;
        for (const auto& [k, v] : modes.items()) names.push_back(k);
        const std::vector<std::string_view> views(names.begin(), names.end());
        fail(mp, "no mode " + inQuotes(modeName) + suggestion(modeName, views, "modes"));
    }
    Suite s;
    const Json& m = modes.at(modeName);
    const JsonPath p = mp.key(modeName);
    requireObject(m, p, kModeKeys);
    SuiteMode& o = s.mode;
    o.width = integer(m, p, "width", 1);
    o.height = integer(m, p, "height", 1);
    o.maxSpp = integer(m, p, "max_spp", 1);
    o.seeds = integer(m, p, "seeds", 1);
    o.referenceSpp = integer(m, p, "reference_spp", 1);
    o.referenceBatches = integer(m, p, "reference_batches", 1);
    o.peerMaxSpp = integer(m, p, "peer_max_spp", 1);
    o.peerReferenceSpp = optionalInteger(m, p, "peer_reference_spp", o.referenceSpp, 1);
    o.peerTimingRuns = optionalInteger(m, p, "peer_timing_runs", 1, 1);
    o.peerExtendSpp = optionalInteger(m, p, "peer_extend_spp", o.peerMaxSpp, o.peerMaxSpp, "peer_max_spp");
    o.peerDecideSpp = optionalInteger(m, p, "peer_decide_spp", o.peerExtendSpp, o.peerExtendSpp, "peer_extend_spp");
    o.extendSpp = optionalInteger(m, p, "extend_spp", o.maxSpp, o.maxSpp, "max_spp");
    if (m.contains("peer_thresholds")) {
        const Json& t = m.at("peer_thresholds");
        const JsonPath tp = p.key("peer_thresholds");
        if (!t.is_array()) fail(tp, "expected an array of noise thresholds, got " + typeOf(t));
        for (std::size_t i = 0; i < t.size(); ++i) {
            const double v = t[i].is_number() ? t[i].get<double>() : -1.0;
            if (!(v > 0.0 && v < 1.0))
                fail(tp.index(i), "expected a noise threshold in (0, 1), got " + (t[i].is_number() ? t[i].dump() : typeOf(t[i])));
            if (i > 0 && !(v < o.peerThresholds.back()))
                fail(tp.index(i), "the thresholds must decrease, and " + t[i].dump() + " follows " + t[i - 1].dump());
            o.peerThresholds.push_back(v);
        }
    }

    const Json& scenes = member(doc, top, "scenes");
    const JsonPath sp = top.key("scenes");
    if (!scenes.is_array() || scenes.empty()) fail(sp, "expected a non-empty array of scenes, got " + typeOf(scenes));
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        const Json& e = scenes[i];
        const JsonPath ep = sp.index(i);
        requireObject(e, ep, kSceneKeys);
        SuiteScene scene;
        scene.name = text(e, ep, "name");
        for (const SuiteScene& earlier : s.scenes)
            if (earlier.name == scene.name) fail(ep.key("name"), "the name " + inQuotes(scene.name) + " is given twice");
        scene.scene = text(e, ep, "scene");
        if (e.contains("analytic")) {
            const Json& a = e.at("analytic");
            if (!a.is_number() || !std::isfinite(a.get<double>()) || a.get<double>() < 0)
                fail(ep.key("analytic"), "expected a number >= 0 (the image's exact value), got " +
                                             (a.is_number() ? a.dump() : typeOf(a)));
            scene.analytic = true;
            scene.analyticValue = glm::vec3(a.get<float>());
        }
        scene.peer = boolean(e, ep, "peer", false);
        if (e.contains("variants")) {
            const Json& vs = e.at("variants");
            const JsonPath vp = ep.key("variants");
            if (!vs.is_array()) fail(vp, "expected an array of variants, got " + typeOf(vs));
            for (std::size_t k = 0; k < vs.size(); ++k) {
                const JsonPath kp = vp.index(k);
                requireObject(vs[k], kp, kVariantKeys);
                std::string name = text(vs[k], kp, "name");
                const Json& set = member(vs[k], kp, "set");
                std::vector<std::string> overrides;
                if (!set.is_array()) fail(kp.key("set"), "expected an array of KEY=VALUE strings, got " + typeOf(set));
                for (std::size_t j = 0; j < set.size(); ++j) {
                    if (!set[j].is_string() || set[j].get_ref<const std::string&>().find('=') == std::string::npos)
                        fail(kp.key("set").index(j), "expected a KEY=VALUE string, got " +
                                                         (set[j].is_string() ? set[j].dump() : typeOf(set[j])));
                    overrides.push_back(set[j].get<std::string>());
                }
                scene.variants.emplace_back(std::move(name), std::move(overrides));
            }
        }
        s.scenes.push_back(std::move(scene));
    }
    return s;
}

} // namespace

Suite readSuite(const std::filesystem::path& file, const std::string& mode) {
    const std::string name = file.string();
    std::ifstream in(file, std::ios::binary);
    if (!in) throw SuiteError(name + ": error: cannot read the suite file");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    const std::string textOfFile = buffer.str();
    ParseResult parsed = parseJson(textOfFile);
    const JsonLocator locator(textOfFile);
    if (std::string error = documentError(parsed, locator, name); !error.empty()) throw SuiteError(error);
    try {
        return build(parsed.doc, mode);
    } catch (const ValidationFailure& f) {
        throw SuiteError(placeFailure(f, name, locator, {}));
    }
}

} // namespace raylab
