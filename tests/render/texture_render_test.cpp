// Image textures through the whole path: a scene file names a PNG, the loader reads it, the GPU
// samples it at the hit's uv.
#include "io/image_io.h"
#include "render_helpers.h"
#include "scene/transform.h"
#include "shaders/include/camera.glsl"
#include "support/gl_test.h"
#include "support/statistics.h"

#include <OpenImageIO/imageio.h>

#include <array>
#include <set>

#include <filesystem>
#include <fstream>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

// 8×8 RGB PNG, top row first as files store it: blue | white over red | green.
void writeQuadrantsPng(const fs::path& path) {
    std::vector<unsigned char> px;
    for (int row = 0; row < 8; ++row)
        for (int x = 0; x < 8; ++x) {
            const bool top = row < 4, left = x < 4;
            const unsigned char r = (!top && left) || (top && !left) ? 255 : 0;
            const unsigned char g = (!top && !left) || (top && !left) ? 255 : 0;
            const unsigned char b = top ? 255 : 0;
            px.insert(px.end(), {r, g, b});
        }
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(path.string(), OIIO::ImageSpec(8, 8, 3, OIIO::TypeDesc::UINT8)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
    out->close();
}

fs::path scratch() {
    const fs::path dir = fs::temp_directory_path() / ("raylab_texture_test_" + std::to_string(::getpid()));
    fs::create_directories(dir / "textures");
    return dir;
}

constexpr const char* kQuadScene = R"({
  "camera": { "position": [0, 0, 2], "look_at": [0, 0, 0], "fov": 40 },
  "render": { "width": 16, "height": 16, "spp": 4, "max_bounces": 1, "rr_depth": 100, "nee": false, "tone_map": "clamp" },
  "sky": { "type": "constant", "color": 1 },
  "materials": { "checker": { "albedo": 1, "albedo_texture": "textures/quadrants.png" } },
  "objects": [ { "type": "mesh", "material": "checker",
    "positions": [-1,-1,0, 1,-1,0, 1,1,0, -1,1,0], "indices": [0,1,2, 0,2,3], "uvs": [0,0, 1,0, 1,1, 0,1] } ] })";

// A checker of nu × nv cells, each `texels` × `texels` texels of one colour that names the cell:
// r = (i + ½)/nu, g = (j + ½)/nv (i along u, j along v from the bottom), b alternating. Written
// as a linear EXR (exact values on the GPU), top row first as files store it.
struct Checker {
    int nu, nv, texels;
    glm::vec3 colour(int i, int j) const {
        return {(float(i) + 0.5f) / float(nu), (float(j) + 0.5f) / float(nv), (i + j) % 2 ? 0.8f : 0.2f};
    }
    // The colour at the centre of the cell that contains uv (in [0, 1)²).
    glm::vec3 at(glm::vec2 uv) const { return colour(int(uv.x * float(nu)), int(uv.y * float(nv))); }
    void write(const fs::path& path) const {
        Image image(nu * texels, nv * texels);
        for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
                const glm::vec3 c = colour(x / texels, (image.height - 1 - y) / texels);
                float* p = &image.rgba[(std::size_t(y) * std::size_t(image.width) + std::size_t(x)) * 4];
                p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = 1.0f;
            }
        writeImage(path, image, {}, {});
    }
};

// The pixel (column, row from the top) whose centre sees world point p through the scene's
// pinhole camera (camera.glsl: ndc (−1, −1) is the image's bottom-left corner), or (−1, −1).
glm::ivec2 pixelOf(const Scene& scene, glm::vec3 p) {
    const Camera& c = scene.camera;
    const float aspect = float(scene.render.width) / float(scene.render.height);
    const glsl::CameraBasis cam = glsl::cameraBasis(c.position, c.lookAt, c.up, c.fovY, aspect);
    const glm::vec3 d = p - cam.origin;
    const float depth = glm::dot(d, cam.forward);
    const glm::vec2 ndc(glm::dot(d, cam.right) / depth / (cam.tanHalfFovY * cam.aspect),
                        glm::dot(d, cam.up) / depth / cam.tanHalfFovY);
    const int x = int(std::floor((ndc.x + 1.0f) * 0.5f * float(scene.render.width)));
    const int y = scene.render.height - 1 - int(std::floor((ndc.y + 1.0f) * 0.5f * float(scene.render.height)));
    if (depth <= 0.0f || x < 0 || y < 0 || x >= scene.render.width || y >= scene.render.height) return {-1, -1};
    return {x, y};
}

} // namespace

class TextureRenderTest : public test::GlTest {};

TEST_F(TextureRenderTest, UvCheckerLandsWhereExpectedOnAQuad) {
    const fs::path dir = scratch();
    writeQuadrantsPng(dir / "textures" / "quadrants.png");
    std::ofstream(dir / "quad.json") << kQuadScene;
    const Scene scene = loadScene(dir / "quad.json");
    ASSERT_EQ(scene.textures.size(), 1u);
    // The quad fills the view (it spans ±1 at distance 2; the view ±0.73). One bounce reaches the
    // sky (radiance 1), so a pixel is exactly the texture's linear colour there.
    const Image image = test::render(scene);
    // Pixel centres well inside each quadrant (away from the bilinear seams), image top row first.
    const struct { int x, y; glm::vec3 colour; } probes[] = {
        {3, 3, {0, 0, 1}}, {12, 3, {1, 1, 1}}, {3, 12, {1, 0, 0}}, {12, 12, {0, 1, 0}}};
    for (const auto& p : probes)
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(image.rgb(p.x, p.y)[c], p.colour[c], 1e-5f) << p.x << "," << p.y << " channel " << c;
    fs::remove_all(dir);
}

TEST_F(TextureRenderTest, MissingAndBrokenImagesAreLocatedErrors) {
    const fs::path dir = scratch();
    std::ofstream(dir / "quad.json") << kQuadScene;
    try {
        loadScene(dir / "quad.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_EQ(std::string(e.what()), (dir / "quad.json").string() +
                                             ":5:62: error: materials.checker.albedo_texture: " +
                                             (dir / "textures" / "quadrants.png").string() +
                                             ": cannot read: no such file");
    }
    std::ofstream(dir / "textures" / "quadrants.png") << "not a png";
    try {
        loadScene(dir / "quad.json");
        FAIL() << "no error";
    } catch (const SceneError& e) {
        EXPECT_NE(std::string(e.what()).find("materials.checker.albedo_texture: " +
                                             (dir / "textures" / "quadrants.png").string() + ": "),
                  std::string::npos)
            << e.what();
    }
    fs::remove_all(dir);
}

TEST_F(TextureRenderTest, ManyTexturesOfDifferentSizes) {
    // Two quads side by side, each with its own texture (5×3 magenta, 2×7 cyan: odd sizes, so
    // every mip level has a different shape), plus the 8×8 one unused by any object: each quad
    // must find its own texels in the shared buffer.
    const fs::path dir = scratch();
    auto uniform = [&](const std::string& name, int w, int h, std::array<unsigned char, 3> rgb) {
        std::vector<unsigned char> px;
        for (int i = 0; i < w * h; ++i) px.insert(px.end(), rgb.begin(), rgb.end());
        auto out = OIIO::ImageOutput::create((dir / "textures" / name).string());
        ASSERT_TRUE(out);
        ASSERT_TRUE(out->open((dir / "textures" / name).string(), OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::UINT8)));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data()));
        out->close();
    };
    writeQuadrantsPng(dir / "textures" / "quadrants.png");
    uniform("magenta.png", 5, 3, {255, 0, 255});
    uniform("cyan.png", 2, 7, {0, 255, 255});
    std::ofstream(dir / "two.json") << R"({
      "camera": { "position": [0, 0, 2], "look_at": [0, 0, 0], "fov": 40 },
      "render": { "width": 16, "height": 16, "spp": 4, "max_bounces": 1, "rr_depth": 100, "nee": false, "tone_map": "clamp" },
      "sky": { "type": "constant", "color": 1 },
      "materials": { "a": { "albedo": 1, "albedo_texture": "textures/quadrants.png" },
                     "b": { "albedo": 1, "albedo_texture": "textures/magenta.png" },
                     "c": { "albedo": [1, 0.5, 1], "albedo_texture": "textures/cyan.png" } },
      "objects": [
        { "type": "mesh", "material": "b", "positions": [-1,-1,0, 0,-1,0, 0,1,0, -1,1,0],
          "indices": [0,1,2, 0,2,3], "uvs": [0,0, 1,0, 1,1, 0,1] },
        { "type": "mesh", "material": "c", "positions": [0,-1,0, 1,-1,0, 1,1,0, 0,1,0],
          "indices": [0,1,2, 0,2,3], "uvs": [0,0, 1,0, 1,1, 0,1] },
        { "type": "sphere", "center": [0, 0, 50], "radius": 1, "material": "a" } ] })";
    const Scene scene = loadScene(dir / "two.json");
    ASSERT_EQ(scene.textures.size(), 3u);
    const Image image = test::render(scene);
    for (int y : {2, 8, 13}) {
        EXPECT_NEAR(image.rgb(3, y)[0], 1.0f, 1e-5f);
        EXPECT_NEAR(image.rgb(3, y)[1], 0.0f, 1e-5f);
        EXPECT_NEAR(image.rgb(3, y)[2], 1.0f, 1e-5f);
        EXPECT_NEAR(image.rgb(12, y)[0], 0.0f, 1e-5f);
        EXPECT_NEAR(image.rgb(12, y)[1], 0.5f, 1e-5f) << "albedo multiplies the texture";
        EXPECT_NEAR(image.rgb(12, y)[2], 1.0f, 1e-5f);
    }
    fs::remove_all(dir);
}

TEST_F(TextureRenderTest, NormalMapChangesShadingAsPredicted) {
    // A quad facing the camera (+z) under a sky whose radiance is (d.y + 1) / 2, albedo 1, one
    // bounce. A normal map tilting every normal towards +v (= +y) by asin 0.6 makes the cosine
    // lobe look up: the pixel value is ∫ cosθ'/π · [d.z > 0] · (d.y + 1)/2 dω around the tilted
    // normal (directions under the quad end the path), integrated numerically here.
    const fs::path dir = scratch();
    {
        std::vector<float> px;
        for (int i = 0; i < 4 * 4; ++i) px.insert(px.end(), {0.5f, 0.8f, 0.9f});   // n = (0, 0.6, 0.8)
        auto out = OIIO::ImageOutput::create((dir / "textures" / "tilt.exr").string());
        ASSERT_TRUE(out);
        ASSERT_TRUE(out->open((dir / "textures" / "tilt.exr").string(), OIIO::ImageSpec(4, 4, 3, OIIO::TypeDesc::FLOAT)));
        ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, px.data()));
        out->close();
    }
    std::ofstream(dir / "nm.json") << R"({
      "camera": { "position": [0, 0, 2], "look_at": [0, 0, 0], "fov": 40 },
      "render": { "width": 16, "height": 16, "spp": 256, "max_bounces": 1, "rr_depth": 100, "nee": false, "tone_map": "clamp" },
      "sky": { "type": "gradient", "top": 1, "bottom": 0 },
      "materials": { "bumpy": { "albedo": 1, "normal_texture": "textures/tilt.exr" } },
      "objects": [ { "type": "mesh", "material": "bumpy",
        "positions": [-1,-1,0, 1,-1,0, 1,1,0, -1,1,0], "indices": [0,1,2, 0,2,3], "uvs": [0,0, 1,0, 1,1, 0,1] } ] })";
    const Scene scene = loadScene(dir / "nm.json");
    const Image image = test::render(scene);
    // Prediction: midpoint rule over (θ', φ') around n = (0, 0.6, 0.8).
    const glm::dvec3 n(0.0, 0.6, 0.8), t(1.0, 0.0, 0.0), b = glm::cross(n, t);
    double expected = 0.0;
    const int steps = 1000;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            const double th = (i + 0.5) * (M_PI / 2) / steps, ph = (j + 0.5) * 2 * M_PI / steps;
            const glm::dvec3 d = std::sin(th) * std::cos(ph) * t + std::sin(th) * std::sin(ph) * b + std::cos(th) * n;
            if (d.z <= 0.0) continue;
            expected += std::cos(th) / M_PI * (d.y + 1.0) / 2.0 * std::sin(th) * (M_PI / 2 / steps) * (2 * M_PI / steps);
        }
    const std::vector<double> v = test::channel(image, 1);
    const double m = test::mean(v), se = test::standardError(v);
    EXPECT_NEAR(m, expected, 4.0 * se) << "expected " << expected;
    EXPECT_GT(expected - 0.5, 20.0 * se) << "the map must make a visible difference from the flat 0.5";
    fs::remove_all(dir);
}

TEST_F(TextureRenderTest, UvCheckerLandsWhereExpectedOnASphere) {
    // The sphere's uv (bvh_traversal.glsl surfaceAt) is longitude and latitude of its normal n:
    // u = ½ + atan2(n.z, n.x) / 2π (u = ½ towards +x, ¾ towards +z), v = acos(−n.y) / π (0 at the
    // bottom pole). An 8 × 4 checker of 4 × 4-texel cells, each its own colour, seen from 8
    // cameras around the sphere (latitudes ±30°, four longitudes): the pixel that sees the centre
    // of a cell, wherever it faces the camera (cos > 0.55), is exactly that cell's colour. Under a
    // uniform sky of radiance 1 with one bounce a Lambertian pixel is its albedo; a pixel's
    // footprint (< 0.06 units) stays inside the ±1.5 texels (≥ 0.13 units) around a cell's centre
    // where bilinear filtering gives the cell's colour, and the ray cones pick level 0 or 1.
    const fs::path dir = scratch();
    const Checker checker{8, 4, 4};
    checker.write(dir / "textures" / "checker.exr");
    const glm::vec3 centre(0.5f, -0.2f, 0.3f);
    const float radius = 1.2f;
    std::ofstream(dir / "sphere.json") << R"({
      "render": { "width": 64, "height": 64, "spp": 4, "max_bounces": 1, "rr_depth": 100, "nee": false, "tone_map": "clamp" },
      "sky": { "type": "constant", "color": 1 },
      "materials": { "checker": { "albedo": 1, "albedo_texture": "textures/checker.exr" } },
      "objects": [ { "type": "sphere", "center": [0.5, -0.2, 0.3], "radius": 1.2, "material": "checker" } ] })";
    Scene scene = loadScene(dir / "sphere.json");
    ASSERT_EQ(scene.textures.size(), 1u);
    scene.camera.lookAt = centre;
    scene.camera.fovY = 45.0f;
    auto normalAt = [](float u, float v) {   // the inverse of the uv above
        const float phi = 2.0f * glsl::PI * (u - 0.5f), theta = glsl::PI * v;
        return glm::vec3(std::sin(theta) * std::cos(phi), -std::cos(theta), std::sin(theta) * std::sin(phi));
    };
    PathTracer tracer;
    std::set<int> cellsSeen;
    int probes = 0;
    for (float lat : {30.0f, -30.0f})
        for (float u : {0.125f, 0.375f, 0.625f, 0.875f}) {
            const float l = glm::radians(lat), phi = 2.0f * glsl::PI * (u - 0.5f);
            const glm::vec3 view(std::cos(l) * std::cos(phi), std::sin(l), std::cos(l) * std::sin(phi));
            scene.camera.position = centre + 3.0f * radius * view;
            tracer.setScene(scene);
            renderProgressively(tracer, scene.render);
            const Image image = tracer.readImage();
            for (int j = 0; j < checker.nv; ++j)
                for (int i = 0; i < checker.nu; ++i) {
                    const glm::vec2 uv((float(i) + 0.5f) / float(checker.nu), (float(j) + 0.5f) / float(checker.nv));
                    const glm::vec3 n = normalAt(uv.x, uv.y);
                    if (glm::dot(n, view) < 0.55f) continue;
                    const glm::ivec2 px = pixelOf(scene, centre + radius * n);
                    ASSERT_GE(px.x, 0);
                    ++probes;
                    cellsSeen.insert(j * checker.nu + i);
                    const glm::vec3 want = checker.colour(i, j), got = image.rgb(px.x, px.y);
                    for (int c = 0; c < 3; ++c)
                        EXPECT_NEAR(got[c], want[c], 1e-5f) << "cell " << i << "," << j << " at pixel " << px.x << ","
                                                             << px.y << " seen from latitude " << lat << ", u " << u;
                }
        }
    EXPECT_EQ(cellsSeen.size(), std::size_t(checker.nu * checker.nv)) << "every cell probed at least once";
    RecordProperty("probes", probes);
    fs::remove_all(dir);
}

TEST_F(TextureRenderTest, UvCheckerLandsWhereExpectedOnAMeshFromAnObjFile) {
    // A cube written as an OBJ file (v / vt / f v/vt), placed by a rotation, scale and translation
    // in the scene. Face k maps to its own block of 2 × 2 cells of an 8 × 8 checker, with its uv
    // corners turned k quarter turns and odd faces mirrored, so a face read at the wrong place,
    // the wrong way round or upside down shows another cell's colour. On each face the camera
    // sees (cos > 0.3), the pixel at each quadrant's centre must be the colour of the cell that
    // quadrant's uv falls in.
    const fs::path dir = scratch();
    const Checker checker{8, 8, 4};
    checker.write(dir / "textures" / "checker.exr");
    // Each face: a corner and two edges (outward normal = e1 × e2).
    const struct { glm::vec3 corner, e1, e2; } faces[] = {
        {{1, -1, 1}, {0, 0, -2}, {0, 2, 0}},  {{-1, -1, -1}, {0, 0, 2}, {0, 2, 0}},
        {{-1, 1, 1}, {2, 0, 0}, {0, 0, -2}},  {{-1, -1, -1}, {2, 0, 0}, {0, 0, 2}},
        {{-1, -1, 1}, {2, 0, 0}, {0, 2, 0}},  {{1, -1, -1}, {-2, 0, 0}, {0, 2, 0}}};
    // uv of face k at (s, t) ∈ [0, 1]² along (e1, e2).
    auto faceUv = [](int k, float s, float t) {
        glm::vec2 q(s, t);
        if (k % 2) q.x = 1.0f - q.x;                                 // mirrored
        for (int r = 0; r < k % 4; ++r) q = glm::vec2(1.0f - q.y, q.x);   // quarter turns
        const glm::vec2 block(float(2 * (k % 4)), float(4 * (k / 4)));   // in cells
        return (block + 2.0f * q) / 8.0f;
    };
    {
        std::ofstream obj(dir / "cube.obj");
        obj << "# a cube, one uv block per face (written by texture_render_test.cpp)\n";
        const glm::vec2 st[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int k = 0; k < 6; ++k)
            for (const glm::vec2& c : st) {
                const glm::vec3 p = faces[k].corner + c.x * faces[k].e1 + c.y * faces[k].e2;
                const glm::vec2 uv = faceUv(k, c.x, c.y);
                obj << "v " << p.x << " " << p.y << " " << p.z << "\nvt " << uv.x << " " << uv.y << "\n";
            }
        for (int k = 0; k < 6; ++k) {
            const int b = 4 * k + 1;
            obj << "f " << b << "/" << b << " " << b + 1 << "/" << b + 1 << " " << b + 2 << "/" << b + 2 << "\n";
            obj << "f " << b << "/" << b << " " << b + 2 << "/" << b + 2 << " " << b + 3 << "/" << b + 3 << "\n";
        }
    }
    std::ofstream(dir / "cube.json") << R"({
      "camera": { "position": [1.1, 2.75, 5.01], "look_at": [0.2, 0.1, -0.3], "fov": 35 },
      "render": { "width": 96, "height": 96, "spp": 4, "max_bounces": 1, "rr_depth": 100, "nee": false, "tone_map": "clamp" },
      "sky": { "type": "constant", "color": 1 },
      "materials": { "checker": { "albedo": 1, "albedo_texture": "textures/checker.exr" } },
      "objects": [ { "type": "mesh", "file": "cube.obj", "material": "checker",
        "transform": { "translation": [0.2, 0.1, -0.3], "rotation": [15, -25, 10], "scale": 0.8 } } ] })";
    const Scene scene = loadScene(dir / "cube.json");
    ASSERT_EQ(scene.meshes.size(), 1u);
    ASSERT_EQ(scene.meshes[0].uvs.size(), scene.meshes[0].positions.size());
    const Image image = test::render(scene);
    const glm::mat4 toWorld = transformMatrix(scene.meshes[0].transform);
    int facesSeen = 0;
    for (int k = 0; k < 6; ++k) {
        const glm::vec3 normal = glm::normalize(glm::mat3(toWorld) * glm::cross(faces[k].e1, faces[k].e2));
        const glm::vec3 middle = glm::vec3(toWorld * glm::vec4(faces[k].corner + 0.5f * (faces[k].e1 + faces[k].e2), 1.0f));
        if (glm::dot(normal, glm::normalize(scene.camera.position - middle)) < 0.3f) continue;
        ++facesSeen;
        for (float s : {0.25f, 0.75f})
            for (float t : {0.25f, 0.75f}) {
                const glm::vec3 p = glm::vec3(toWorld * glm::vec4(faces[k].corner + s * faces[k].e1 + t * faces[k].e2, 1.0f));
                const glm::ivec2 px = pixelOf(scene, p);
                ASSERT_GE(px.x, 0);
                const glm::vec3 want = checker.at(faceUv(k, s, t)), got = image.rgb(px.x, px.y);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(got[c], want[c], 1e-5f) << "face " << k << " at (" << s << ", " << t << "), pixel "
                                                         << px.x << "," << px.y;
            }
    }
    EXPECT_EQ(facesSeen, 3);
    fs::remove_all(dir);
}
