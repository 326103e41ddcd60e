// libFuzzer harness of the glTF loader: the input is written as fuzz.glb when it starts with the
// binary container's magic "glTF", else as fuzz.gltf, in the scratch folder (whose tiny.bin and
// tiny.ppm an external uri may name), and read with loadGltfAsset as the scene builder reads it.
// Only GltfError is expected.
#include "fuzz_support.h"

#include "scene/gltf_loader.h"

#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    if (raylab::fuzz::namesASpecialFile(input)) return -1;
    const bool binary = input.substr(0, 4) == "glTF";
    const std::filesystem::path file = raylab::fuzz::scratchDir() / (binary ? "fuzz.glb" : "fuzz.gltf");
    raylab::fuzz::writeFile(file, input);
    try {
        raylab::loadGltfAsset(file);
    } catch (const raylab::GltfError&) {
    } catch (const std::exception& e) {
        raylab::fuzz::unexpected("fuzz_gltf", e.what());
    }
    return 0;
}
