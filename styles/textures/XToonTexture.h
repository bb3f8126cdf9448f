#pragma once

// XToonTexture: the generated default tone map of the xtoon style.

#include "styles/textures/TextureImage.h"

namespace nprgl::styles {

// An X-Toon tone map (Barla, Thollot and Markosian, NPAR 2006): u is the diffuse term
// (L.n from -1 to 1), v the detail attribute (0: full detail; 1: the most abstract). Row
// v = 0 holds three cel bands with soft edges; going up they flatten towards one light tone,
// so far or grazing parts read as simpler, lighter shapes (level of abstraction, back-light).
class XToonTexture {
public:
    static constexpr int kWidth = 256;
    static constexpr int kHeight = 64;
    static TextureImage generate();
};

} // namespace nprgl::styles
