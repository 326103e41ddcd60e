#pragma once
// The tracer's camera on the CPU: the very cameraBasis/cameraRay of shaders/include/camera.glsl
// and intersectSphere of sphere.glsl, so a click picks the object the tracer shows in that pixel
// and an overlay box projects onto the pixels where the tracer draws the box's edges.
// Image coordinates: x right, y down, pixel (0, 0) the top-left one; pixel centres at +0.5.
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

// The object (index into scene.spheres) seen at image point (x, y) of a width × height image,
// through its centre ray; nullopt for the sky.
std::optional<int> pickObject(const Scene& scene, int width, int height, ImagePoint point);
// The distance along that ray to the hit (for click-to-focus); nullopt for the sky.
std::optional<float> pickDistance(const Scene& scene, int width, int height, ImagePoint point);

struct Box {
    glm::vec3 lo{0.0f};
    glm::vec3 hi{0.0f};
};
Box objectBounds(const Sphere& sphere);

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
