#pragma once

#include "common/PngImage.h"

#include <string>

namespace nprgl::styles::strokes {

// The stroke texture of thesis Fig. 4.17: one image along u holding the start cap
// [0, u1), a middle [u1, u2] that tiles seamlessly, and the end cap (u2, 1]; v runs across
// the stroke. Coverage is in alpha, rgb is a multiplier for the stroke colour (white = the
// colour itself). The procedural kinds are made by code here (deterministic, no binaries).
class StrokeTexture {
public:
    enum class Kind { Pencil = 0, Ink = 1, Brush = 2, Chalk = 3 };
    static constexpr float kU1 = 0.25f, kU2 = 0.75f;
    static constexpr int kWidth = 512, kHeight = 32;

    static void generate(Kind kind, PngImage& out);
    // Reads a user PNG. An image without transparency is read as dark strokes on light
    // paper (coverage = 1 - luminance). False with a message when it cannot be read.
    static bool load(const std::string& path, PngImage& out, std::string& error);
};

} // namespace nprgl::styles::strokes
