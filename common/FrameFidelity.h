#pragma once

// FrameFidelity: how closely a styled frame keeps a native one, per pixel and per object.

#include "common/PngImage.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace nprgl {

// CIELAB (D65) of an 8-bit sRGB colour, and the CIE76 colour difference ΔE*ab.
struct Lab {
    float l = 0.0f, a = 0.0f, b = 0.0f;
    static Lab fromSrgb(const uint8_t* rgb);
    static float deltaE(const Lab& x, const Lab& y);
};

// The measure of one frame: `native` the program's (style none), `styled` the same frame in a
// style, `ids` the same frame in the `ids` style (which object each pixel shows; may be
// empty: no per-object figures). All three of one size.
struct FrameFidelity {
    static constexpr float kMatch = 10.0f;    // ΔE*ab at or below it: the same colour
    static constexpr float kDrawn = 3.0f;     // ΔE*ab above it from the clear colour: drawn
    static constexpr float kChromatic = 10.0f; // chroma below it: no hue to keep
    static constexpr float kHueKept = 20.0f;  // degrees
    static constexpr float kLighterBy = 10.0f; // L* apart: an order the style must keep
    static constexpr float kOrderSlack = 5.0f; // L* the other way: reversed (less: evened)
    static constexpr uint32_t kPaletteMinPixels = 64; // fewer: too small to judge

    struct Tone {
        float lightness = 0.0f, chroma = 0.0f, hue = 0.0f; // L*, C*ab, h in degrees
    };
    struct Object {
        uint32_t id = 0;
        uint32_t pixels = 0;
        double meanDeltaE = 0.0;
        Tone native, styled;
        std::array<int, 4> box{0, 0, 0, 0}; // x0, y0, x1, y1 inclusive, top row 0
        bool judged = false;     // large enough for the palette check
        bool hueKept = true;     // styled hue within kHueKept of native's (or no hue)
        bool orderKept = true;   // lightness ordered against the others as native's
        bool paletteOk() const { return hueKept && orderKept; }
    };

    uint8_t clear[3] = {0, 0, 0}; // the frame's clear colour, as the native frame shows it
    bool clearFromStream = false; // given by the replay, not guessed from the border
    uint64_t drawn = 0;          // drawn natively or by an object in the style
    uint64_t nativeDrawn = 0;
    // Drawn pixels within kMatch of native, the style's pixel or one of its eight neighbours
    // (rasterisation may put an edge or a speck a pixel apart).
    uint64_t matching = 0;
    // Drawn natively; in the style no object covers it and it shows the style's background
    // (the clear colour or the page, as where the program drew nothing), which the native
    // pixel did not look like.
    uint64_t missing = 0;
    std::vector<Object> objects; // by id
    PngImage diff;               // native | styled | where they differ (measure(..., true))

    double fidelity() const { return drawn ? double(matching) / double(drawn) : 1.0; }
    double missingShare() const
    {
        return nativeDrawn ? double(missing) / double(nativeDrawn) : 0.0;
    }
    uint32_t paletteFailures() const;
    uint32_t paletteJudged() const;

    // False with a message when the images cannot be compared (sizes differ).
    // `shading`: the same frame in the chain without its outline styles (may be empty: the
    // styled frame): the objects' styled tones, which the palette check judges, are its. Ink
    // is no object's colour: on a thin part (a wire, a bar) it covers most of its pixels.
    // `clear`: the colour the frame's last clear of the whole window left (the replay knows
    // it; nullptr: the frame did not clear it all, and its border's commonest colour is used).
    static bool measure(const PngImage& native, const PngImage& styled, const PngImage& ids,
                        bool makeDiff, FrameFidelity& out, std::string& error,
                        const PngImage& shading = PngImage(), const uint8_t* clear = nullptr);
    // How the `ids` style writes object id 1..kMaxId: red the low byte, green the high one,
    // blue a fixed mark; idOf() is 0 for a colour that is no id.
    static constexpr uint32_t kMaxId = 0xFFFF;
    static constexpr uint8_t kIdMark = 0xA5;
    static void idColour(uint32_t id, uint8_t rgb[3])
    {
        rgb[0] = uint8_t(id & 0xFF);
        rgb[1] = uint8_t((id >> 8) & 0xFF);
        rgb[2] = kIdMark;
    }
    static uint32_t idOf(const uint8_t* rgb)
    {
        return rgb[2] == kIdMark ? (uint32_t(rgb[0]) | uint32_t(rgb[1]) << 8) : 0;
    }
    // The most common colour of the native frame's border: what a program that did not clear
    // the whole window most likely shows where it drew nothing.
    static void clearColour(const PngImage& native, uint8_t rgb[3]);
};

} // namespace nprgl
