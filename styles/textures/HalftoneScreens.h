#pragma once

#include "styles/textures/TextureImage.h"

#include <string>

namespace nprgl::styles {

// The halftone screens of thesis §3.3 (grey: 0 ink, 255 none). A is the light screen, B the
// medium one, C the dark one; combine() folds them into the one texture H the shader reads.
// Each generated screen ramps from 0 in the middle of its primitives to its edge, so the
// combined H grows almost continuously and the shader's thresholding grows the ink smoothly
// (dots swell, lines thicken) instead of switching whole grey patterns.
class HalftoneScreens {
public:
    enum class Pattern { Dots, Lines, Noise, Bricks };

    struct Set {
        TextureImage a, b, c; // an empty screen counts as blank (no ink)
    };

    static bool parsePattern(const std::string& name, Pattern& out);
    // Deterministic tiles of size x size texels (size a multiple of 32).
    static Set make(Pattern pattern, int size = 128);
    // B remapped to (0.33, 1), C to (0.66, 1), texel = min(A', B', C'). All non-empty screens
    // must have A's size; grey channel only (RGBA screens use their red channel).
    static TextureImage combine(const Set& screens);
};

} // namespace nprgl::styles
