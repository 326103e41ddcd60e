// Meshes through the whole GPU path: a transformed closed triangle mesh in a white furnace.
#include "render_helpers.h"
#include "support/gl_test.h"

using namespace raylab;

namespace {

// A cube of half-size 1 as 12 triangles, with a transform that rotates one of its vertical edges
// towards the camera and scales it unevenly; the camera sees nothing but the cube.
constexpr const char* kCubeFurnace = R"({
  "camera": { "position": [0, 0, 4], "look_at": [0, 0, 0], "fov": 8 },
  "render": { "width": 32, "height": 32, "spp": 8, "max_bounces": 8, "rr_depth": 100, "nee": false, "tone_map": "clamp" },
  "sky": { "type": "constant", "color": 1 },
  "materials": { "grey": { "albedo": 0.5 } },
  "objects": [ { "type": "mesh", "material": "grey",
    "positions": [-1,-1,-1, 1,-1,-1, 1,1,-1, -1,1,-1, -1,-1,1, 1,-1,1, 1,1,1, -1,1,1],
    "indices": [0,2,1, 0,3,2, 4,5,6, 4,6,7, 0,1,5, 0,5,4, 3,7,6, 3,6,2, 0,4,7, 0,7,3, 1,2,6, 1,6,5],
    "transform": { "translation": [0.1, 0, 0], "rotation": [20, 45, 0], "scale": [1.5, 1, 1.2] } } ]
})";

} // namespace

class MeshRenderTest : public test::GlTest {};

TEST_F(MeshRenderTest, TransformedCubeInAWhiteFurnaceIsExactlyAlbedoEverywhere) {
    // Convex: every camera ray must hit (no cracks along the edge and corners in view), and every
    // bounce ray must leave without hitting the cube again (no self-hits through the instance
    // transform): then each sample is exactly 0.5, in every pixel, for both entry points.
    const Scene scene = parseScene(kCubeFurnace, "cube_furnace.json");
    for (TracerEntry entry : {TracerEntry::Fragment, TracerEntry::Compute}) {
        const Image image = test::render(scene, {entry, 8, 8, {}});
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x)
                for (int c = 0; c < 3; ++c)
                    ASSERT_NEAR(image.rgb(x, y)[c], 0.5f, 1e-6f) << "pixel " << x << "," << y << " entry " << int(entry);
    }
}

TEST_F(MeshRenderTest, MovingTheMeshKeepsItsBvhAndTheRenderFollows) {
    Scene scene = parseScene(kCubeFurnace, "cube_furnace.json");
    GpuScene gpu;
    gpu.upload(scene);
    const auto nodes = gpu.geometry().meshNodes.size();
    scene.meshes[0].transform.translation.x = 100.0f;   // out of view
    gpu.updateTransforms(scene);
    EXPECT_EQ(gpu.geometry().meshNodes.size(), nodes);
    // Through the tracer: moved out of view, the image is the sky.
    PathTracer tracer;
    tracer.setScene(parseScene(kCubeFurnace, "cube_furnace.json"));
    tracer.renderPass();
    EXPECT_NEAR(tracer.readImage().rgb(16, 16)[0], 0.5f, 1e-6f);
    tracer.updateTransforms(scene);
    EXPECT_EQ(tracer.samplesPerPixel(), 0u);
    tracer.renderPass();
    EXPECT_NEAR(tracer.readImage().rgb(16, 16)[0], 1.0f, 1e-6f);
}
