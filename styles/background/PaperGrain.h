#pragma once

#include "styles/textures/TextureImage.h"

#include <cstdint>

namespace nprgl::styles {

// A tile of paper structure (grey: 255 leaves the page as it is, darker texels are where the
// sheet takes a little more pigment): soft cloudy formation, fine tooth and scattered short
// fibres. Deterministic for a seed and seamless when repeated.
class PaperGrain {
public:
    struct Options {
        int size = 256;      // tile edge in texels; a multiple of 64
        int fibres = 260;    // short fibres per tile
        float cloud = 0.10f; // depth of the cloudy formation
        float tooth = 0.12f; // depth of the fine tooth
        float fibre = 0.30f; // darkness of a dark fibre (light ones are half as strong)
        uint32_t seed = 11;
    };
    static TextureImage make(const Options& options);
};

} // namespace nprgl::styles
