#pragma once

#include "styles/textures/TextureImage.h"

namespace nprgl::styles {

// Stippling tiles (grey: 255 paper, 0 ink): small round dots scattered on a jittered grid, so
// they look random but never clump; seamless when repeated.
class StippleTexture {
public:
    struct Options {
        int size = 120;      // tile edge in texels
        int cell = 5;        // one dot candidate per cell; divides size
        float radius = 0.9f; // mean dot radius in texels
        float fill = 0.8f;   // share of cells that get a dot
        uint32_t seed = 3;
    };
    static TextureImage make(const Options& options);
};

} // namespace nprgl::styles
