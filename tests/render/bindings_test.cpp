// Binding points come from shaders/include/bindings.glsl alone: the tracer's storage buffers do
// not share a point, and no shader or host file writes a point as a bare number.
#include "shaders/include/bindings.glsl"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

namespace fs = std::filesystem;

namespace {

// Every storage buffer the path tracer's program can declare (its debug variants included).
constexpr std::array kTracerStorageBuffers = {
    BINDING_SPHERES,          BINDING_MATERIALS,        BINDING_COUNTERS,
    BINDING_SPHERE_LIGHTS,    BINDING_ENV_MARGINAL,     BINDING_ENV_CONDITIONAL,
    BINDING_TOP_NODES,        BINDING_MESH_NODES,       BINDING_INSTANCES,
    BINDING_TRIANGLES,        BINDING_VERTICES,         BINDING_TRAVERSAL_COUNTERS,
    BINDING_TEXTURE_INFO,     BINDING_DEBUG_MOMENTS,
    BINDING_DEBUG_HEAT_MAX,   BINDING_INSPECT_BOUNCES,  BINDING_INSPECT_PATHS,
};

template <std::size_t N>
constexpr bool pairwiseDistinct(const std::array<int, N>& points) {
    for (std::size_t i = 0; i < N; ++i)
        for (std::size_t j = i + 1; j < N; ++j)
            if (points[i] == points[j]) return false;
    return true;
}

static_assert(pairwiseDistinct(kTracerStorageBuffers), "two tracer storage buffers share a binding point");
// The self-test's sampler runs with the scene's buffers bound, so its output has a point of its own.
static_assert(pairwiseDistinct(std::array{BINDING_SPHERES, BINDING_MATERIALS, BINDING_COUNTERS, BINDING_SPHERE_LIGHTS,
                                          BINDING_ENV_MARGINAL, BINDING_ENV_CONDITIONAL, BINDING_BSDF_SAMPLES}));
static_assert(BINDING_TEST_INPUT != BINDING_TEST_OUTPUT);
// The tracer's texture units: the sky map, the texel views of the geometry, the textures, the
// materials and the lights (the accumulation texture is the display pass's, a program of its own).
static_assert(pairwiseDistinct(std::array{BINDING_SKY_MAP_TEXTURE, BINDING_TOP_NODE_TEXELS, BINDING_MESH_NODE_TEXELS,
                                          BINDING_INSTANCE_TEXELS, BINDING_TRIANGLE_TEXELS, BINDING_TEXTURE_TEXELS,
                                          BINDING_MATERIAL_TEXELS, BINDING_TRIANGLE_LIGHT_TEXELS,
                                          BINDING_LIGHT_ALIAS_TEXELS, BINDING_TRIANGLE_LIGHT_INDEX_TEXELS}),
              "two tracer texture units coincide");

// `binding = 3` in a layout, or a glBind* call whose point is a number.
const std::regex kLiteralPoint(
    R"(binding\s*=\s*[0-9])"
    R"(|glBind(BufferBase|BufferRange)\s*\(\s*\w+\s*,\s*[0-9])"
    R"(|glBind(TextureUnit|ImageTexture)\s*\(\s*[0-9])");

} // namespace

TEST(Bindings, NoShaderOrHostFileWritesABindingPointAsANumber) {
    const fs::path root = RAYLAB_SOURCE_DIR;
    int files = 0;
    for (const char* top : {"shaders", "src", "ui", "tests/support"})
        for (const auto& e : fs::recursive_directory_iterator(root / top)) {
            const std::string ext = e.path().extension().string();
            if (ext != ".glsl" && ext != ".comp" && ext != ".frag" && ext != ".vert" && ext != ".cpp" && ext != ".h")
                continue;
            ++files;
            std::ifstream in(e.path());
            std::string line;
            for (int n = 1; std::getline(in, line); ++n)
                EXPECT_FALSE(std::regex_search(line, kLiteralPoint))
                    << fs::relative(e.path(), root).string() << ":" << n << ": a literal binding point; use a BINDING_* "
                    << "name of shaders/include/bindings.glsl\n    " << line;
        }
    EXPECT_GT(files, 50);
}

// The GPU belongs to src/render: the viewer binds no buffer, image or texture unit itself.
TEST(Bindings, TheViewerBindsNoBufferOfItsOwn) {
    const fs::path root = RAYLAB_SOURCE_DIR;
    const std::regex bind(R"(glBind(BufferBase|BufferRange|TextureUnit|ImageTexture)\s*\()");
    for (const auto& e : fs::recursive_directory_iterator(root / "ui")) {
        if (e.path().extension() != ".cpp" && e.path().extension() != ".h") continue;
        std::ifstream in(e.path());
        std::string line;
        for (int n = 1; std::getline(in, line); ++n)
            EXPECT_FALSE(std::regex_search(line, bind))
                << fs::relative(e.path(), root).string() << ":" << n << ": binds a GPU resource; that is src/render's job\n    "
                << line;
    }
}
