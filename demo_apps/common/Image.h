#pragma once

#include <cstdint>
#include <vector>

namespace demo {

// 8-bit RGB pixels, top row first.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgb;
};

} // namespace demo
