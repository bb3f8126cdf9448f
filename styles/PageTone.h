#pragma once

// PageTone: whether this frame's page is dark (the program's background is) or light.

#include <glm/glm.hpp>

#include <cstdint>

namespace nprgl::styles {

// A program that clears to black keeps a dark page and gets light ink; one that clears to a
// light colour gets paper and dark ink. Decided from the clear colour of each frame's first
// flush, with hysteresis and a hold of a few frames, so a program whose background fades or
// flashes does not flip the page back and forth. paper.tone overrides it (light, dark).
class PageTone {
public:
    enum class Mode { Auto = 0, Light = 1, Dark = 2 };

    void setMode(Mode mode) { mMode = mode, mDark = mode == Mode::Dark, mDecided = false; }
    // The clear colour of a flush of `frame`; only a frame's first counts.
    void observe(uint64_t frame, glm::vec3 clear);
    bool dark() const { return mDark; }

    // The ink for lines and marks: configured for a light page; on a dark page a dark ink
    // is lifted to the same hue at the lightness a light page gives black ink's contrast.
    glm::vec3 ink(glm::vec3 configured) const;
    // A line class's colour: the ink mixed by `lightness` (0..1) away from the ink, towards
    // the page's side (white on a light page, black on a dark one).
    glm::vec3 line(glm::vec3 configured, float lightness) const;

    // Relative luminance of a (gamma-encoded) colour, 0..1.
    static float luminance(glm::vec3 c);

    static constexpr float kDarkBelow = 0.18f;  // luminance: a light page turns dark below it
    static constexpr float kLightAbove = 0.30f; // and a dark page light above it
    static constexpr int kHoldFrames = 6;       // frames the other tone must last to switch

private:
    Mode mMode = Mode::Auto;
    bool mDark = false;
    bool mDecided = false;
    uint64_t mFrame = UINT64_MAX;
    int mOther = 0; // frames in a row that asked for the other tone
};

} // namespace nprgl::styles
