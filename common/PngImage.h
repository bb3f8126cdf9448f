#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace nprgl {

// An 8-bit RGBA image, top row first.
struct PngImage {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;

    // Writes the image; on failure returns false and says why in error.
    bool write(const std::string& path, std::string& error) const;
    // Reads any 8-bit or 16-bit PNG, converted to RGBA8.
    static bool read(const std::string& path, PngImage& out, std::string& error);
    // Reverses the row order (GL reads the bottom row first).
    void flipRows();
    // Alpha 255 everywhere: a framebuffer's picture as a window shows it (the window system
    // ignores the alpha a program leaves; a viewer of the PNG would not).
    void makeOpaque();
};

} // namespace nprgl
