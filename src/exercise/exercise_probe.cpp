#include "exercise/exercise_probe.h"

#include "render/shader_variant.h"
#include "shaders/include/bindings.glsl"

#include <glad/gl.h>

namespace raylab {
namespace {

ShaderDefines probeDefines(const std::string& slotDefine, const std::filesystem::path& pupilFile) {
    ShaderDefines defines = featureDefines(allFeatures());
    defines.emplace_back(slotDefine, "\"" + std::filesystem::absolute(pupilFile).string() + "\"");
    return defines;
}

} // namespace

ExerciseProbe::ExerciseProbe(const std::string& slotDefine, const std::filesystem::path& pupilFile)
    : program_(ShaderProgram::compute("entry/exercise_probe.comp", probeDefines(slotDefine, pupilFile))) {}

std::vector<ProbeOutput> ExerciseProbe::run(ProbeMode mode, const std::vector<ProbeInput>& inputs) const {
    const auto count = static_cast<unsigned>(inputs.size());
    std::vector<ProbeOutput> out(inputs.size());
    if (count == 0) return out;
    GLuint buffers[2] = {0, 0};
    glCreateBuffers(2, buffers);
    glNamedBufferStorage(buffers[0], GLsizeiptr(count * sizeof(ProbeInput)), inputs.data(), 0);
    glNamedBufferStorage(buffers[1], GLsizeiptr(count * sizeof(ProbeOutput)), nullptr, GL_MAP_READ_BIT);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_TEST_INPUT, buffers[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, BINDING_TEST_OUTPUT, buffers[1]);
    program_.set("uCount", count);
    program_.set("uMode", static_cast<int>(mode));
    glUseProgram(program_.id());
    glDispatchCompute((count + 63) / 64, 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(buffers[1], 0, GLsizeiptr(count * sizeof(ProbeOutput)), out.data());
    glDeleteBuffers(2, buffers);
    return out;
}

} // namespace raylab
