// libFuzzer harness of the OBJ loader: the input is written as fuzz.obj in the scratch folder and
// read with loadObj, as the scene builder reads an object's "file". Only ObjError is expected.
#include "fuzz_support.h"

#include "scene/obj_loader.h"

#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view input(reinterpret_cast<const char*>(data), size);
    const std::filesystem::path file = raylab::fuzz::scratchDir() / "fuzz.obj";
    raylab::fuzz::writeFile(file, input);
    try {
        raylab::loadObj(file);
    } catch (const raylab::ObjError&) {
    } catch (const std::exception& e) {
        raylab::fuzz::unexpected("fuzz_obj", e.what());
    }
    return 0;
}
