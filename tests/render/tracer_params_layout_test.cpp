// The tracer's parameter block as the GL driver lays it out (std140) against the C++ struct the
// host uploads (shaders/include/tracer_params.glsl): a field that moves, changes size or exists on
// one side only fails here.
#include "render_helpers.h"
#include "shaders/include/tracer_params.glsl"
#include "support/gl_test.h"

#include <glad/gl.h>

#include <cstddef>
#include <map>
#include <string>
#include <vector>

using namespace raylab;
using raylab::test::GlTest;

namespace {

struct Field {
    std::size_t offset;
    std::size_t size;
};

#define RAYLAB_FIELD(name) \
    {"TracerParams." #name, {offsetof(glsl::TracerParams, name), sizeof(glsl::TracerParams::name)}}
const std::map<std::string, Field> kCppFields = {
    RAYLAB_FIELD(sampleStart),      RAYLAB_FIELD(rpp),           RAYLAB_FIELD(imageSize),
    RAYLAB_FIELD(seed),             RAYLAB_FIELD(maxBounces),    RAYLAB_FIELD(rrDepth),
    RAYLAB_FIELD(sphereCount),      RAYLAB_FIELD(camOrigin),     RAYLAB_FIELD(camTanHalfFovY),
    RAYLAB_FIELD(camRight),         RAYLAB_FIELD(camAspect),     RAYLAB_FIELD(camUp),
    RAYLAB_FIELD(camLensRadius),    RAYLAB_FIELD(camForward),    RAYLAB_FIELD(camFocusDistance),
    RAYLAB_FIELD(skyColor),         RAYLAB_FIELD(camPixelSpread), RAYLAB_FIELD(skyTop),
    RAYLAB_FIELD(skyType),          RAYLAB_FIELD(skyBottom),     RAYLAB_FIELD(skyMapScale),
    RAYLAB_FIELD(skyRotation),      RAYLAB_FIELD(envMeanWeight), RAYLAB_FIELD(lightCount),
    RAYLAB_FIELD(triangleLightCount), RAYLAB_FIELD(nee),         RAYLAB_FIELD(mis),
    RAYLAB_FIELD(skyIsLight),       RAYLAB_FIELD(sampleCount),   RAYLAB_FIELD(aoDistance),
    RAYLAB_FIELD(aoRays),           RAYLAB_FIELD(fragmentStripTiles), RAYLAB_FIELD(fragmentStripBlocks),
};
#undef RAYLAB_FIELD

std::size_t glTypeSize(GLint type) {
    switch (type) {
    case GL_FLOAT:
    case GL_INT:
    case GL_UNSIGNED_INT:
    case GL_BOOL: return 4;
    case GL_INT_VEC2: return 8;
    case GL_FLOAT_VEC3: return 12;
    default: return 0;   // a type the block does not use yet: add it here
    }
}

} // namespace

class TracerParamsLayoutTest : public GlTest {};

TEST_F(TracerParamsLayoutTest, DriverOffsetsAndSizeEqualTheCppStruct) {
    PathTracer tracer;
    tracer.setScene(loadScene(test::scenePath("furnace.json")));
    const GLuint program = tracer.program().id();

    const GLuint block = glGetProgramResourceIndex(program, GL_UNIFORM_BLOCK, "TracerParams");
    ASSERT_NE(block, GL_INVALID_INDEX) << "the tracer has no TracerParams block";
    const GLenum blockProps[] = {GL_BUFFER_DATA_SIZE, GL_NUM_ACTIVE_VARIABLES, GL_BUFFER_BINDING};
    GLint blockValues[3] = {};
    glGetProgramResourceiv(program, GL_UNIFORM_BLOCK, block, 3, blockProps, 3, nullptr, blockValues);
    EXPECT_EQ(std::size_t(blockValues[0]), sizeof(glsl::TracerParams));
    EXPECT_EQ(std::size_t(blockValues[1]), kCppFields.size()) << "a field exists on one side only";
    EXPECT_EQ(blockValues[2], BINDING_TRACER_PARAMS_UBO);

    std::vector<GLint> members(static_cast<std::size_t>(blockValues[1]));
    const GLenum activeProp = GL_ACTIVE_VARIABLES;
    glGetProgramResourceiv(program, GL_UNIFORM_BLOCK, block, 1, &activeProp, GLsizei(members.size()), nullptr,
                           members.data());
    for (GLint member : members) {
        char name[128] = {};
        glGetProgramResourceName(program, GL_UNIFORM, GLuint(member), sizeof(name), nullptr, name);
        const GLenum props[] = {GL_OFFSET, GL_TYPE};
        GLint values[2] = {};
        glGetProgramResourceiv(program, GL_UNIFORM, GLuint(member), 2, props, 2, nullptr, values);
        const auto cpp = kCppFields.find(name);
        ASSERT_NE(cpp, kCppFields.end()) << name << " is in the GLSL block but not in the C++ struct";
        EXPECT_EQ(std::size_t(values[0]), cpp->second.offset) << name;
        EXPECT_EQ(glTypeSize(values[1]), cpp->second.size) << name;
    }
}
