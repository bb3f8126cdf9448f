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
// read before and after, and OverlayLegibility::measure tells what the draw changed and how
// it stands out. Analysis only: two read-backs per draw.
class OverlayContrast {
public:
    using Draw = OverlayDraw; // contrast 1 when it changed nothing or has no surroundings

    // For the whole process (a replay): every compositor measures from now on, except while
    // paused (frames the replay does not write).
    static void enable();
    static bool enabled();
    static void setPaused(bool paused);
    static bool measuring();

    // Around one draw into the window (width x height); after() without a before() is
    // ignored, a read that cannot be made measures nothing (said once).
    void before(const ContextCaps& caps, int width, int height);
    void after();
    // The draws measured since the last call, in the order drawn.
    std::vector<Draw> takeFrame();

private:
    void unread(const char* why);

    const ContextCaps* mCaps = nullptr;
    int mWidth = 0, mHeight = 0;
    bool mOpen = false;
    uint64_t mUnread = 0;
    std::vector<uint8_t> mBefore, mAfter;
    std::vector<Draw> mFrame;
};

} // namespace nprgl
