#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace demo {

// A tiny 5x7 font (digits, the capitals the demos write, ':' and ' ') drawn at double size
// with glBitmap: what the demos' 2D overlays write their text with.
class BitmapFont {
public:
    static constexpr int kWidth = 10; // pixels, after doubling
    static constexpr int kHeight = 14;
    static constexpr int kAdvance = 12;

    BitmapFont();
    // Draws text from the current raster position with the current pixel-unpack state
    // (rows are two bytes: an alignment of 1 or 2). Unknown characters draw as spaces.
    void draw(std::string_view text) const;

private:
    // Bottom row first, two bytes per row, most significant bit left.
    using Bitmap = std::array<uint8_t, kHeight * 2>;
    static constexpr int kGlyphs = 24;
    std::array<Bitmap, kGlyphs> mBitmaps{};
};

} // namespace demo
