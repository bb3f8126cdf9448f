#include "styles/textures/StippleTexture.h"

#include "styles/textures/TextureNoise.h"

#include <algorithm>
#include <cmath>

namespace nprgl::styles {

TextureImage StippleTexture::make(const Options& o)
{
    const int cells = o.size / o.cell;
    TextureImage t = TextureImage::grey(o.size, o.size, 255);
    for (int y = 0; y < o.size; ++y) {
        for (int x = 0; x < o.size; ++x) {
            const float px = float(x) + 0.5f, py = float(y) + 0.5f;
            const int cx = x / o.cell, cy = y / o.cell;
            float ink = 0.0f;
            // A dot can reach into neighbouring cells; wrap the neighbours for tiling.
            for (int j = cy - 1; j <= cy + 1; ++j) {
                for (int i = cx - 1; i <= cx + 1; ++i) {
                    const int wi = (i + cells) % cells, wj = (j + cells) % cells;
                    if (TextureNoise::hash(o.seed, wi, wj) > o.fill) continue;
                    const float jx = TextureNoise::hash(o.seed + 1, wi, wj);
                    const float jy = TextureNoise::hash(o.seed + 2, wi, wj);
                    const float r =
                        o.radius * (0.75f + 0.5f * TextureNoise::hash(o.seed + 3, wi, wj));
                    const float dx = px - (float(i) + 0.15f + 0.7f * jx) * float(o.cell);
                    const float dy = py - (float(j) + 0.15f + 0.7f * jy) * float(o.cell);
                    const float dist = std::sqrt(dx * dx + dy * dy);
                    ink = std::max(ink, std::clamp(r - dist + 0.5f, 0.0f, 1.0f));
                }
            }
            t.at(x, y) = uint8_t(std::lround(255.0f * (1.0f - ink)));
        }
    }
    return t;
}

} // namespace nprgl::styles
