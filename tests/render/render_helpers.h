#pragma once
#include "render/path_tracer.h"
#include "render/progressive_render.h"
#include "scene/scene_loader.h"

#include <cmath>
#include <string>
#include <vector>

namespace raylab::test {

inline std::string scenePath(const std::string& name) {
    return std::string(RAYLAB_SOURCE_DIR) + "/scenes/" + name;
}

// Renders to settings.spp and returns the image.
inline Image render(const Scene& scene, TracerOptions options = {}) {
    PathTracer tracer(options);
    tracer.setScene(scene);
    renderProgressively(tracer, scene.render);
    return tracer.readImage();
}

// One colour channel of every pixel.
inline std::vector<double> channel(const Image& image, int c) {
    std::vector<double> v;
    for (size_t i = 0; i < image.rgba.size(); i += 4) v.push_back(image.rgba[i + size_t(c)]);
    return v;
}

inline double rmse(const Image& a, const Image& b) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < a.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const double d = double(a.rgba[i]) - double(b.rgba[i]);
        sum += d * d;
        ++n;
    }
    return std::sqrt(sum / double(n));
}

} // namespace raylab::test
