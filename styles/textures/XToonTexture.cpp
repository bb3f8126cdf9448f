#include "styles/textures/XToonTexture.h"

#include <algorithm>
#include <cmath>

namespace nprgl::styles {

namespace {

float smooth(float edge0, float edge1, float x)
{
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

} // namespace

TextureImage XToonTexture::generate()
{
    TextureImage image;
    image.width = kWidth;
    image.height = kHeight;
    image.channels = 4;
    image.pixels.resize(size_t(kWidth) * kHeight * 4);
    constexpr float kShadow = 0.42f, kMid = 0.72f, kLight = 1.0f, kFlat = 0.82f;
    for (int y = 0; y < kHeight; ++y) {
        const float v = float(y) / float(kHeight - 1);
        for (int x = 0; x < kWidth; ++x) {
            const float u = (float(x) + 0.5f) / float(kWidth);
            // Bands at L.n = -0.1 and 0.5, 2% of the axis soft.
            float band = kShadow;
            band += (kMid - kShadow) * smooth(0.44f, 0.46f, u);
            band += (kLight - kMid) * smooth(0.74f, 0.76f, u);
            // Abstraction: the bands fade into one tone, a little lighter where lit.
            const float flat = kFlat + 0.1f * (u - 0.5f);
            const float tone = band + (flat - band) * v;
            uint8_t* p = &image.pixels[(size_t(y) * kWidth + x) * 4];
            p[0] = p[1] = p[2] = uint8_t(std::lround(255.0f * std::clamp(tone, 0.0f, 1.0f)));
            p[3] = 255;
        }
    }
    return image;
}

} // namespace nprgl::styles
