#include "styles/textures/XToonTexture.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace nprgl::styles {

namespace {

float smooth(float edge0, float edge1, float x)
{
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

} // namespace

TextureImage XToonTexture::generate(int bands)
{
    bands = std::clamp(bands, kMinBands, kMaxBands);
    TextureImage image;
    image.width = kWidth;
    image.height = kHeight;
    image.channels = 4;
    image.pixels.resize(size_t(kWidth) * kHeight * 4);
    constexpr float kShadow = 0.42f, kMid = 0.72f, kLight = 1.0f, kFlat = 0.82f;
    // The band tones on the curve shadow - mid - light, evenly in the band index; the band
    // edges evenly between L.n = -0.1 and 0.5 (one edge: at -0.1, where shadow begins), so
    // that more bands split the lit side rather than pushing the shadow further round.
    std::vector<float> tones(static_cast<size_t>(bands));
    std::vector<float> edges(static_cast<size_t>(bands - 1));
    for (int k = 0; k < bands; ++k) {
        const float t = float(k) / float(bands - 1);
        tones[size_t(k)] = t <= 0.5f ? kShadow + (kMid - kShadow) * (2.0f * t)
                                     : kMid + (kLight - kMid) * (2.0f * t - 1.0f);
    }
    for (int k = 0; k + 1 < bands; ++k) {
        edges[size_t(k)] = bands == 2 ? 0.45f : 0.45f + 0.3f * float(k) / float(bands - 2);
    }
    for (int y = 0; y < kHeight; ++y) {
        const float v = float(y) / float(kHeight - 1);
        for (int x = 0; x < kWidth; ++x) {
            const float u = (float(x) + 0.5f) / float(kWidth);
            // Each edge 2% of the axis soft.
            float band = tones[0];
            for (int k = 0; k + 1 < bands; ++k) {
                const float e = edges[size_t(k)];
                band += (tones[size_t(k) + 1] - tones[size_t(k)]) * smooth(e - 0.01f, e + 0.01f, u);
            }
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
