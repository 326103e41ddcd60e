#pragma once
// A linear float RGBA image, top row first (the order image files use).
#include <glm/glm.hpp>

#include <vector>

namespace raylab {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgba;   // width × height × 4

    Image() = default;
    Image(int w, int h) : width(w), height(h), rgba(static_cast<size_t>(w) * h * 4, 0.0f) {}

    glm::vec4 at(int x, int y) const {
        const size_t i = (static_cast<size_t>(y) * width + x) * 4;
        return {rgba[i], rgba[i + 1], rgba[i + 2], rgba[i + 3]};
    }
    glm::vec3 rgb(int x, int y) const { return glm::vec3(at(x, y)); }
};

} // namespace raylab
