#pragma once

// OverlayLegibility: whether a styled frame's 2D overlays keep the contrast the program's had.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace nprgl {

// One 2D draw as a replay's --overlays measured it (frame/OverlayContrast): the pixels it
// changed, and WCAG's contrast ratio between them and their surroundings.
struct OverlayDraw {
    uint32_t pixels = 0;
    float contrast = 1.0f;
    bool surrounded = false; // it had surroundings (a full-window quad has none)
};

// The same frame's 2D draws natively and in a style, paired in the order drawn (a style
// leaves them all, so both replays draw the same ones). A draw keeps its legibility when its
// styled contrast is at least the smaller of native's and kTarget, and it is still seen:
// drawn over a page of its own colour it changes few pixels and counts as contrast 1. One
// the style shows on many more pixels than natively (black text under the program's text,
// on its black background: seen only where it crossed the scene) has gained, not lost.
struct OverlayLegibility {
    // A draw's pixels are those it changed (a channel by more than kChanged). It is judged
    // as the end of its run of 2D draws shows it: a shadow or outline pass by the text drawn
    // over it, a panel with the text on it. Its surroundings are the pixels within kRing of
    // its own that neither it nor a later draw of the run changed (a glyph against the page or
    // panel around it, a panel against the scene around it). Each of its pixels is given WCAG 2's
    // ratio against the surroundings' mean relative luminance, and the draw the kStrokes quantile
    // of them.
    static constexpr int kRing = 2;
    static constexpr int kChanged = 4;
    static constexpr double kStrokes = 0.9;
    static constexpr float kTarget = 4.5f;     // WCAG 2 AA for text
    static constexpr uint32_t kMinPixels = 16; // fewer: a speck or a cursor, not judged
    static constexpr float kSlack = 0.95f;     // antialiasing moves a ratio a little
    static constexpr float kSeen = 0.5f;       // of native's pixels, changed in the style
    static constexpr float kGained = 2.0f;     // times native's pixels: shown, not lost

    struct Short {
        size_t index = 0; // the frame's n-th measured 2D draw, from 0
        uint32_t pixels = 0;
        float native = 1.0f, styled = 1.0f;
    };
    size_t judged = 0;
    std::vector<Short> shortOf;
    std::string mismatch; // the two replays measured different draws: nothing judged

    // The pixels (y * width + x) a draw changed, from the window before and after it (RGBA
    // rows of `width`); and the draw of those pixels as `shown` (its run's end) shows it,
    // `later` (one byte per pixel, may be null) marking what the run's later draws changed.
    static void changedPixels(const uint8_t* before, const uint8_t* after, int width, int height,
                              std::vector<uint32_t>& out);
    static OverlayDraw measure(const std::vector<uint32_t>& pixels, const uint8_t* shown, int width,
                               int height, const uint8_t* later = nullptr);
    // WCAG 2: relative luminance of an 8-bit sRGB colour, and the ratio of two luminances.
    static double luminance(const uint8_t* rgb);
    static float ratio(double l1, double l2);
    // The replay's --overlays text, "3 measured: 120:12.41 0:- 4000:-" (pixels:contrast, -
    // without surroundings); parse is false on anything else.
    static std::string describe(const std::vector<OverlayDraw>& draws);
    static bool parse(const std::string& text, std::vector<OverlayDraw>& out);
    static OverlayLegibility judge(const std::vector<OverlayDraw>& native,
                                   const std::vector<OverlayDraw>& styled);
    // "2 of 14 short of their contrast (worst: draw 3, 220 px, 12.1:1 natively, 1.3:1)".
    std::string summary() const;
};

} // namespace nprgl
