// OverlayContrast: how far each 2D draw left in the window stands out from its surroundings.
#pragma once

#include "common/OverlayLegibility.h"

#include <cstdint>
#include <string>
#include <vector>

namespace nprgl {

struct ContextCaps;

// For a replay's --overlays figures (nprgl compare's legibility check). Around each 2D draw
// the compositor leaves in the window (text, HUD, bitmaps, orthographic quads) the window is
// read, which gives the pixels the draw changed. A run of 2D draws ends at anything else that
// draws (a 3D draw, a clear, a blit) and at the frame's end; then each of its draws is
// measured as the run's end shows it (OverlayLegibility::measure). Analysis only: a
// read-back per draw.
class OverlayContrast {
public:
    using Draw = OverlayDraw; // contrast 1 when it changed nothing or has no surroundings

    // For the whole process (a replay): every compositor measures from now on, except while
    // paused (frames the replay does not write).
    static void enable();
    static bool enabled();
    static void setPaused(bool paused);
    static bool measuring();

    // Around one 2D draw into the window (width x height); end() without a begin() is
    // ignored. A read that cannot be made leaves the run unmeasured (said once).
    void begin(const ContextCaps& caps, int width, int height);
    void end();
    void endRun();
    // The draws measured since the last call, in the order drawn (the open run ended).
    std::vector<Draw> takeFrame();

private:
    void unread(const char* why);

    const ContextCaps* mCaps = nullptr;
    int mWidth = 0, mHeight = 0;
    bool mRun = false;  // a run is open: mAfter is the window as its last draw left it
    bool mOpen = false; // begin() read the window for the draw under way
    uint64_t mUnread = 0;
    std::vector<uint8_t> mBefore, mAfter, mLater;
    std::vector<std::vector<uint32_t>> mRunPixels; // each draw of the run: what it changed
    std::vector<Draw> mFrame;
};

} // namespace nprgl
