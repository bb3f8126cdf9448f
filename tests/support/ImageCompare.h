#pragma once

#include "common/PngImage.h"

#include <string>

namespace nprgl::test {

struct ImageDiff {
    bool comparable = false; // both read, same size
    std::string error;
    size_t differingPixels = 0;
    int maxChannelDelta = 0;
};

// Compares two PNG files pixel by pixel (RGB only: GLX visuals may lack alpha); a pixel
// differs when a channel differs by more than `tolerance`.
ImageDiff compareImages(const std::string& a, const std::string& b, int tolerance = 0);

// Share of pixels that are not (near) black: a picture that is all background is suspect.
double coveredFraction(const PngImage& image);

// Checks a 300x300 glxgears frame: its red, green and blue gears are all there.
void expectGlxgearsPicture(const std::string& path);

} // namespace nprgl::test
