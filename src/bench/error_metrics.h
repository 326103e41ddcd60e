#pragma once
// Error of an image against a reference, over the RGB channels of every pixel.
#include "render/image.h"

namespace raylab {

struct ImageError {
    double mse = 0.0;      // mean squared error
    double rmse = 0.0;     // sqrt(mse)
    double relMse = 0.0;   // mean of (I − R)² / (R² + 0.01): Rousselle, Knaus & Zwicker 2011
};

// Throws std::invalid_argument when the sizes differ.
ImageError imageError(const Image& image, const Image& reference);

// Mean of the RGB channels over all pixels.
double imageMean(const Image& image);

} // namespace raylab
