#pragma once
// The tracer's camera on the CPU: the very cameraBasis/cameraRay of shaders/include/camera.glsl,
// and the tracer's own BVH traversal run on the CPU (accel/cpu_traversal.h), so a click picks the
// object (sphere or mesh instance) the tracer shows in that pixel and an overlay box projects onto
// the pixels where the tracer draws the box's edges.
// Image coordinates: x right, y down, pixel (0, 0) the top-left one; pixel centres at +0.5.
// Objects are numbered as app/scene_object.h says: spheres, then mesh instances.
#include "accel/scene_geometry.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <array>
#include <optional>
#include <vector>

namespace raylab::ui {

struct ImagePoint {
    float x = 0.0f;
    float y = 0.0f;
};

// What the pinhole ray through image point (x, y) of a width × height image meets first.
struct ViewHit {
    float t = 0.0f;        // distance along the ray (its direction is unit length)
    float depth = 0.0f;    // the same along the view axis: t·(dir · forward) (click-to-focus)
    int object = -1;       // app/scene_object.h numbering
    int material = -1;     // the material there (a glTF mesh's per-triangle material)
    glm::vec3 position{0.0f};
};
// nullopt for the sky. `geometry` is the scene's as the tracer traverses it (Viewer::geometry()).
std::optional<ViewHit> viewHit(const Scene& scene, const SceneGeometry& geometry, int width, int height,
                               ImagePoint point);
// The object seen there; nullopt for the sky.
std::optional<int> pickObject(const Scene& scene, const SceneGeometry& geometry, int width, int height,
                              ImagePoint point);
// The same for tests and one-off use: builds the scene's geometry (every mesh's BVH) first.
std::optional<int> pickObject(const Scene& scene, int width, int height, ImagePoint point);

struct Box {
    glm::vec3 lo{0.0f};
    glm::vec3 hi{0.0f};
};
// World-space bounds: of a sphere after its transform; of any object (for a mesh instance: the
// axis-aligned box around its transformed object-space bounds, the box the top-level BVH holds).
Box objectBounds(const Sphere& sphere);
std::optional<Box> objectBounds(const Scene& scene, const SceneGeometry& geometry, int object);

struct Segment {
    ImagePoint a;
    ImagePoint b;
};

// Where the world point lands in the image (nullopt when behind or in the eye's plane).
std::optional<ImagePoint> projectPoint(const Scene& scene, int width, int height, glm::vec3 p);
// The world segment a–b as an image segment, clipped to the part in front of the camera.
std::optional<Segment> projectSegment(const Scene& scene, int width, int height, glm::vec3 a, glm::vec3 b);
// The 12 edges of a box as image segments, clipped to the part in front of the camera.
std::vector<Segment> projectBox(const Scene& scene, int width, int height, const Box& box);
// The same for a transformed box given by its corners: corner i is the (i & 1 ? max : min) x,
// (i & 2 ? max : min) y, (i & 4 ? max : min) z corner of the box before the transform.
std::vector<Segment> projectCorners(const Scene& scene, int width, int height, const std::array<glm::vec3, 8>& corners);

} // namespace raylab::ui
