// The viewer's sample-points plot (inspect/sample_points.h) shows the very points the tracer's
// GLSL sampler draws: computed on the CPU, they equal the shader's on OSMesa for every sampler and
// dimension pair.
#include "inspect/sample_points.h"

#include "gl/shader_program.h"
#include "render/shader_variant.h"
#include "shaders/include/bindings.glsl"
#include "support/gl_test.h"

#include <glad/gl.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using namespace raylab;

namespace {

std::vector<glm::vec2> shaderPoints(const ShaderProgram& program, const SamplePointsQuery& q) {
    GLuint buffer = 0;
    glCreateBuffers(1, &buffer);
    glNamedBufferStorage(buffer, GLsizeiptr(q.count * sizeof(glm::vec2)), nullptr, GL_MAP_READ_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_TEST_OUTPUT, buffer);
    glUseProgram(program.id());
    program.set("uCount", q.count);
    program.set("uFirst", q.first);
    program.set("uPixel", glm::ivec2(q.pixel));
    program.set("uSeed", q.seed);
    program.set("uSpp", q.spp);
    program.set("uDim", samplePairDimension(q.pair, q.bounce, q.lens));
    glDispatchCompute((q.count + 63) / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec2> out(q.count);
    glGetNamedBufferSubData(buffer, 0, GLsizeiptr(q.count * sizeof(glm::vec2)), out.data());
    glDeleteBuffers(1, &buffer);
    return out;
}

} // namespace

class SamplePointsTest : public test::GlTest {};

TEST_F(SamplePointsTest, TheComputedPointsAreTheShaders) {
    // Bit-level agreement is expected (integer hashes, one rounding per float); 1e-6 allows the
    // last bit of stratified's division. The test can fail: the points of another seed or
    // another bounce differ far more.
    for (SamplerKind kind : {SamplerKind::Independent, SamplerKind::Stratified, SamplerKind::Sobol, SamplerKind::ZSobol}) {
        SceneFeatures features = allFeatures();
        features.sampler = kind;
        const ShaderProgram program = ShaderProgram::computeFromFile(
            std::filesystem::path(RAYLAB_SOURCE_DIR) / "tests/support/sample_points.comp", featureDefines(features));
        for (SamplePair pair : {SamplePair::Pixel, SamplePair::Lens, SamplePair::Bsdf, SamplePair::Light}) {
            SamplePointsQuery q;
            q.sampler = kind;
            q.pixel = {37, 11};
            q.seed = 5;
            q.spp = 16;
            q.pair = pair;
            q.bounce = pair == SamplePair::Bsdf || pair == SamplePair::Light ? 2 : 0;
            q.first = 13;   // across the end of a round of 16
            q.count = 40;
            const auto cpu = samplePoints(q);
            const auto gpu = shaderPoints(program, q);
            ASSERT_EQ(cpu.size(), gpu.size());
            for (size_t i = 0; i < cpu.size(); ++i) {
                EXPECT_NEAR(cpu[i].x, gpu[i].x, 1e-6f) << int(kind) << " pair " << int(pair) << " sample " << i;
                EXPECT_NEAR(cpu[i].y, gpu[i].y, 1e-6f) << int(kind) << " pair " << int(pair) << " sample " << i;
            }
            SamplePointsQuery other = q;
            other.seed = 6;
            const auto changed = samplePoints(other);
            double moved = 0.0;
            for (size_t i = 0; i < cpu.size(); ++i) moved += glm::length(changed[i] - gpu[i]);
            EXPECT_GT(moved / double(cpu.size()), 0.1) << "another seed, other points";
        }
    }
}
