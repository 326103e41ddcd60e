// raylab-make-sky: writes a procedural equirectangular HDR sky (a test fixture and example for
// sky.map): a blue gradient above the horizon, a warm bright sun disk, a dark brown ground.
// Usage: raylab-make-sky OUTPUT.{hdr,exr} [--width W] [--sun-elevation DEG] [--sun-azimuth DEG]
#include "shaders/include/environment_map.glsl"

#include <CLI/CLI.hpp>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

int main(int argc, char** argv) {
    CLI::App app{"raylab-make-sky: write a procedural equirectangular HDR sky image"};
    std::string output;
    int width = 512;
    float sunElevation = 35.0f, sunAzimuth = 30.0f, sunRadiance = 2000.0f, sunRadius = 1.5f;
    app.add_option("output", output, "Output image (.hdr or .exr)")->required();
    app.add_option("--width", width, "Width in pixels (height is half)")->check(CLI::Range(8, 16384));
    app.add_option("--sun-elevation", sunElevation, "Sun height above the horizon, degrees")->check(CLI::Range(-90.0, 90.0));
    app.add_option("--sun-azimuth", sunAzimuth, "Sun direction, degrees from -z towards +x");
    app.add_option("--sun-radiance", sunRadiance, "Radiance of the sun disk")->check(CLI::NonNegativeNumber);
    app.add_option("--sun-radius", sunRadius, "Angular radius of the sun disk, degrees")->check(CLI::Range(0.01, 45.0));
    CLI11_PARSE(app, argc, argv);

    using raylab::glsl::directionFromEquirect;
    const int height = width / 2;
    const float el = glm::radians(sunElevation), az = glm::radians(sunAzimuth);
    const glm::vec3 sun(std::cos(el) * std::sin(az), std::sin(el), -std::cos(el) * std::cos(az));
    const float cosSun = std::cos(glm::radians(sunRadius));
    std::vector<float> pixels(size_t(width) * size_t(height) * 3);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const glm::vec3 d = directionFromEquirect(
                glm::vec2((float(x) + 0.5f) / float(width), (float(y) + 0.5f) / float(height)), 0.0f);
            glm::vec3 c;
            if (d.y >= 0.0f) {   // sky: pale at the horizon, deep blue overhead, brighter near the sun
                const float t = std::pow(d.y, 0.5f);
                c = glm::mix(glm::vec3(1.0f, 0.95f, 0.85f), glm::vec3(0.25f, 0.45f, 0.9f), t);
                c += glm::vec3(1.0f, 0.8f, 0.5f) * (0.6f * std::pow(std::max(0.0f, glm::dot(d, sun)), 8.0f));
            } else {             // ground
                c = glm::vec3(0.18f, 0.14f, 0.1f) * (0.6f + 0.4f * (1.0f + d.y));
            }
            if (glm::dot(d, sun) >= cosSun) c = glm::vec3(1.0f, 0.9f, 0.75f) * sunRadiance;
            const size_t i = (size_t(y) * size_t(width) + size_t(x)) * 3;
            pixels[i] = c.r;
            pixels[i + 1] = c.g;
            pixels[i + 2] = c.b;
        }
    auto out = OIIO::ImageOutput::create(output);
    if (!out) {
        std::cerr << output << ": error: cannot write: " << OIIO::geterror() << "\n";
        return 1;
    }
    const OIIO::ImageSpec spec(width, height, 3, OIIO::TypeDesc::FLOAT);
    if (!out->open(output, spec) || !out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !out->close()) {
        std::cerr << output << ": error: cannot write: " << out->geterror() << "\n";
        return 1;
    }
    std::cout << output << "\n";
    return 0;
}
