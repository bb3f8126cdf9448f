// OverlayContrast: the window read around each 2D draw, for OverlayLegibility to measure.
#include "frame/OverlayContrast.h"

#include "common/Log.h"
#include "frame/FrameGrabber.h"
#include "shim/RealGl.h"

#include <atomic>

namespace nprgl {

namespace {

std::atomic<bool> gEnabled{false}, gPaused{false};

} // namespace

void OverlayContrast::enable() { gEnabled = true; }
bool OverlayContrast::enabled() { return gEnabled; }
void OverlayContrast::setPaused(bool paused) { gPaused = paused; }
bool OverlayContrast::measuring() { return gEnabled && !gPaused; }

void OverlayContrast::before(const ContextCaps& caps, int width, int height)
{
    mOpen = false;
    if (const char* why = FrameGrabber::cannotRead(caps, width, height)) {
        unread(why);
        return;
    }
    mCaps = &caps;
    mWidth = width;
    mHeight = height;
    mBefore.resize(size_t(width) * size_t(height) * 4);
    if (FrameGrabber::readFrame(caps, width, height, mBefore.data()) != GL_NO_ERROR) {
        unread("the driver refused the read");
        return;
    }
    mOpen = true;
}

void OverlayContrast::after()
{
    if (!mOpen) return;
    mOpen = false;
    mAfter.resize(mBefore.size());
    if (FrameGrabber::readFrame(*mCaps, mWidth, mHeight, mAfter.data()) != GL_NO_ERROR) {
        unread("the driver refused the read");
        return;
    }
    mFrame.push_back(OverlayLegibility::measure(mBefore.data(), mAfter.data(), mWidth, mHeight));
}

void OverlayContrast::unread(const char* why)
{
    // The frame's list then lacks a draw: compare finds the lists differ and judges nothing.
    if (mUnread++ == 0) NPRGL_WARN("a 2D draw could not be measured: %s", why);
}

std::vector<OverlayContrast::Draw> OverlayContrast::takeFrame()
{
    std::vector<Draw> out;
    out.swap(mFrame);
    return out;
}

} // namespace nprgl
