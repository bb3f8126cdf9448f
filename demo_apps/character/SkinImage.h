#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace character {

// A model's texture, 8-bit RGB, bottom row first (as GL wants it).
struct SkinImage {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgb;

    // Reads an uncompressed Windows BMP, 8-bit paletted or 24-bit (what the MD2 models of
    // assimp-testmodels come with). False with a message naming the path otherwise.
    bool loadBmp(const std::string& path, std::string& error);
};

} // namespace character
