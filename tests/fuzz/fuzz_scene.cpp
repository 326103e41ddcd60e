// libFuzzer harness of the scene format: parseScene with --set overrides (what raylab-render and the
// viewer run), then the writer's text of a scene that loaded (what the viewer saves), loaded again.
// Input: the first line holds the overrides, separated by '|'; the rest is the scene text, read as
// scene.json in the scratch folder (so "tiny.obj", "tiny.ppm", "tiny.hdr" name real files).
// Only SceneError is expected; anything else escaping, or a saved scene that does not load back,
// is a finding.
#include "fuzz_support.h"

#include "scene/scene_loader.h"
#include "scene/scene_writer.h"

#include <exception>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace raylab;
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    if (fuzz::namesASpecialFile(input)) return -1;
    const std::size_t eol = input.find('\n');
    const std::string_view setLine = eol == std::string_view::npos ? std::string_view{} : input.substr(0, eol);
    const std::string_view text = eol == std::string_view::npos ? input : input.substr(eol + 1);
    std::vector<std::string> overrides;
    for (std::size_t start = 0; start < setLine.size();) {
        const std::size_t bar = std::min(setLine.find('|', start), setLine.size());
        if (bar > start) overrides.emplace_back(setLine.substr(start, bar - start));
        start = bar + 1;
    }
    const std::string file = (fuzz::scratchDir() / "scene.json").string();
    Scene scene;
    try {
        scene = parseScene(text, file, overrides);
    } catch (const SceneError&) {
        return 0;
    } catch (const std::exception& e) {
        fuzz::unexpected("fuzz_scene: parseScene", e.what());
    }
    std::string saved;
    try {
        saved = sceneToJson(scene, file).dump(2);
        parseScene(saved, file);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz_scene: the saved scene does not load back:\n%s\n", saved.c_str());
        fuzz::unexpected("fuzz_scene: save and reload", e.what());
    }
    return 0;
}
