// SrgbLinear: an 8-bit sRGB component in linear light (IEC 61966-2-1), by table.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>

namespace nprgl {

// A table: a frame has millions of pixels and only 256 values per channel.
inline float srgbLinear(uint8_t c)
{
    static const std::array<float, 256> kTable = [] {
        std::array<float, 256> t{};
        for (int i = 0; i < 256; ++i) {
            const float s = float(i) / 255.0f;
            t[size_t(i)] = s <= 0.04045f ? s / 12.92f : std::pow((s + 0.055f) / 1.055f, 2.4f);
        }
        return t;
    }();
    return kTable[c];
}

} // namespace nprgl
