#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace nprgl::styles {

// A generated or loaded texture on the CPU: 1 channel (grey, R8) or 4 (RGBA8), top row first.
// Tiles are meant to repeat seamlessly.
struct TextureImage {
    int width = 0;
    int height = 0;
    int channels = 1;
    std::vector<uint8_t> pixels;

    bool empty() const { return width <= 0 || height <= 0 || pixels.empty(); }
    static TextureImage grey(int width, int height, uint8_t value)
    {
        TextureImage t;
        t.width = width;
        t.height = height;
        t.channels = 1;
        t.pixels.assign(size_t(width) * size_t(height), value);
        return t;
    }
    uint8_t& at(int x, int y) { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
    uint8_t at(int x, int y) const { return pixels[size_t(y) * size_t(width) + size_t(x)]; }
};

} // namespace nprgl::styles
