#pragma once

#include "styles/textures/TextureImage.h"

namespace nprgl::styles {

// Pen-and-ink hatching tiles (grey: 255 paper, 0 ink) for textured shading (thesis §3.2):
// diagonal strokes whose width wobbles and which break now and then, like a hand-drawn
// pen line, generated deterministically and seamless when repeated.
class HatchTexture {
public:
    struct Options {
        int size = 128;       // tile edge in texels
        int spacing = 8;      // between neighbouring strokes along the tile's axes; divides size
        float width = 1.3f;   // mean stroke width in texels
        bool cross = false;   // add the second diagonal (cross-hatching)
        uint32_t seed = 1;
    };
    static TextureImage make(const Options& options);
};

} // namespace nprgl::styles
