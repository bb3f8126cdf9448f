#pragma once

#include <cstdint>

namespace nprgl::styles {

// Deterministic, tileable noise for the procedural textures: the same seed always gives the
// same texels, so pictures and tests never change from run to run.
class TextureNoise {
public:
    // A well-mixed hash of (seed, a, b) in [0, 1).
    static float hash(uint32_t seed, int a, int b);
    // Smooth value noise in [0, 1) on a lattice of `cell` texels that repeats every `period`
    // texels (period a multiple of cell): texture tiles built from it are seamless.
    static float value(uint32_t seed, float x, float y, int cell, int period);
    // 1D value noise along a line, repeating every `period` units.
    static float line(uint32_t seed, int lineIndex, float t, int cell, int period);
};

} // namespace nprgl::styles
