#include "bench/error_metrics.h"

#include <cmath>
#include <stdexcept>

namespace raylab {

ImageError imageError(const Image& image, const Image& reference) {
    if (image.width != reference.width || image.height != reference.height)
        throw std::invalid_argument("image and reference differ in size");
    ImageError e;
    size_t n = 0;
    for (size_t i = 0; i < image.rgba.size(); ++i) {
        if (i % 4 == 3) continue;
        const double r = reference.rgba[i];
        const double d = double(image.rgba[i]) - r;
        e.mse += d * d;
        e.relMse += d * d / (r * r + 0.01);
        ++n;
    }
    e.mse /= double(n);
    e.relMse /= double(n);
    e.rmse = std::sqrt(e.mse);
    return e;
}

double imageMean(const Image& image) {
    double sum = 0.0;
    size_t n = 0;
    for (size_t i = 0; i < image.rgba.size(); ++i)
        if (i % 4 != 3) {
            sum += image.rgba[i];
            ++n;
        }
    return n ? sum / double(n) : 0.0;
}

} // namespace raylab
