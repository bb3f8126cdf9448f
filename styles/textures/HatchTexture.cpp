#include "styles/textures/HatchTexture.h"

#include "styles/textures/TextureNoise.h"

#include <algorithm>
#include <cmath>

namespace nprgl::styles {

namespace {

// Ink coverage of one family of parallel diagonal strokes at texel centre (x, y). `across`
// runs perpendicular to the strokes (x + y or x - y), `along` runs with them; both wrap with
// the tile so the pattern repeats seamlessly.
float strokeInk(float across, float along, const HatchTexture::Options& o, uint32_t seed)
{
    const int lines = o.size / o.spacing;
    const int k = int(std::floor(across / float(o.spacing) + 0.5f));
    const int index = ((k % lines) + lines) % lines;
    // A slight sideways wobble, a varying width and occasional breaks along each stroke.
    const float wobble = (TextureNoise::line(seed, index, along, 16, o.size) - 0.5f) * 0.8f;
    const float dist = std::abs(across - float(k * o.spacing) - wobble) / std::sqrt(2.0f);
    const float width =
        o.width * (0.7f + 0.6f * TextureNoise::line(seed + 1, index, along, 32, o.size));
    float ink = std::clamp(width * 0.5f - dist + 0.5f, 0.0f, 1.0f);
    const float gap = TextureNoise::line(seed + 2, index, along, 16, o.size);
    ink *= std::clamp((gap - 0.06f) / 0.08f, 0.0f, 1.0f);
    return ink;
}

} // namespace

TextureImage HatchTexture::make(const Options& o)
{
    TextureImage t = TextureImage::grey(o.size, o.size, 255);
    for (int y = 0; y < o.size; ++y) {
        for (int x = 0; x < o.size; ++x) {
            const float px = float(x) + 0.5f, py = float(y) + 0.5f;
            // x + y and x - y shift by the tile size when x or y does: the pattern tiles. The
            // first family rises to the right on screen, as a right-handed artist hatches.
            float ink = strokeInk(px - py + float(o.size), px + py, o, o.seed);
            if (o.cross) {
                ink = std::max(ink, strokeInk(px + py, px - py + float(o.size), o, o.seed + 7));
            }
            t.at(x, y) = uint8_t(std::lround(255.0f * (1.0f - ink)));
        }
    }
    return t;
}

} // namespace nprgl::styles
