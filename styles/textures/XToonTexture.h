#pragma once

// XToonTexture: the generated default tone map of the xtoon style.

#include "styles/textures/TextureImage.h"

namespace nprgl::styles {

// An X-Toon tone map (Barla, Thollot and Markosian, NPAR 2006): u is the diffuse term
// (L.n from -1 to 1), v the detail attribute (0: full detail; 1: the most abstract). Row
// v = 0 holds `bands` cel bands with soft edges (three by default: shadow, mid tone, light);
// going up they flatten towards one light tone, so far or grazing parts read as simpler,
// lighter shapes (level of abstraction, back-light).
class XToonTexture {
public:
    static constexpr int kWidth = 256;
    static constexpr int kHeight = 64;
    static constexpr int kMinBands = 2;
    static constexpr int kMaxBands = 6;
    // bands is clamped to [kMinBands, kMaxBands].
    static TextureImage generate(int bands = 3);
};

} // namespace nprgl::styles
