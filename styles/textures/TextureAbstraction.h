// A program's texture as a drawing: edge-preserving smoothing and a small palette of its own.
#pragma once

#include "styles/textures/TextureImage.h"

#include <glm/glm.hpp>

#include <vector>

namespace nprgl::styles {

// The abstracted version of an RGBA8 texture (TextureImage with 4 channels): its colours
// smoothed within regions but not across their borders (a bilateral filter, run along rows
// then columns, kPasses times), then each texel snapped to the nearest of a few colours found for
// this texture (k-means on a fixed sample), and finally mixed back towards the program's
// texel by `detail` (0: flat colour per region, 1: the program's texture). Alpha is the
// program's, untouched: cut-outs and the alpha test keep their shape. The texture repeats,
// so the filter wraps around its edges. Deterministic: the same image gives the same bytes.
class TextureAbstraction {
public:
    static constexpr int kPaletteSize = 6;
    static constexpr int kSample = 4096;  // texels the palette is found from, at most
    static constexpr int kPasses = 3;     // of the smoothing, each along rows then columns
    static constexpr float kRangeSigma = 0.20f; // colour distance that counts as an edge
    static constexpr float kMergeDistance = 0.12f; // palette colours closer are one

    static TextureImage abstracted(const TextureImage& rgba, float detail);

    // The palette for an image (kPaletteSize colours or fewer, 0..1), weighting texels by
    // alpha so the colour under clear texels does not take a palette entry.
    static std::vector<glm::vec3> palette(const std::vector<glm::vec4>& texels);

private:
    // One bilateral pass along rows (dx=1) or columns (dx=0) of radius r.
    static void smoothPass(std::vector<glm::vec4>& texels, int width, int height, bool rows,
                           int radius);
};

} // namespace nprgl::styles
