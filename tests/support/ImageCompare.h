#pragma once

#include "common/PngImage.h"

#include <cstdint>
#include <string>
#include <vector>

namespace nprgl::test {

struct ImageDiff {
    bool comparable = false; // both read, same size
    std::string error;
    size_t differingPixels = 0;
    int maxChannelDelta = 0;
    // Differing pixels that a one-pixel shift of an edge does not explain: A's colour is not
    // within B's 3x3 neighbourhood there, or B's not within A's. Rasterisers that round a
    // vertex differently (a 32-bit and a 64-bit Mesa) move coverage by a pixel along edges;
    // a lost object, a wrong colour or a wrong matrix leaves pixels off every edge.
    size_t offEdgePixels = 0;
};

// Compares two PNG files pixel by pixel (RGB only: GLX visuals may lack alpha); a pixel
// differs when a channel differs by more than `tolerance`.
ImageDiff compareImages(const std::string& a, const std::string& b, int tolerance = 0);

// A probe's saved frame: the raw RGBA bytes of a file (empty when it cannot be read).
std::vector<uint8_t> readRgba(const std::string& path);
// Pixels whose RGB differ between two raw RGBA frames; -1 when the sizes differ or both
// are empty (nothing to compare).
int differingRgbPixels(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b);

// Share of pixels that are not (near) black: a picture that is all background is suspect.
double coveredFraction(const PngImage& image);

// Checks a 300x300 glxgears frame: its red, green and blue gears are all there.
void expectGlxgearsPicture(const std::string& path);

} // namespace nprgl::test
