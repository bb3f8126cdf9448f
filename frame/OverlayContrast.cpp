// OverlayContrast: the window read around each 2D draw, for OverlayLegibility to measure.
#include "frame/OverlayContrast.h"

#include "common/Log.h"
#include "frame/FrameGrabber.h"
#include "shim/RealGl.h"

#include <atomic>
#include <utility>

namespace nprgl {

namespace {

std::atomic<bool> gEnabled{false}, gPaused{false};

} // namespace

void OverlayContrast::enable() { gEnabled = true; }
bool OverlayContrast::enabled() { return gEnabled; }
void OverlayContrast::setPaused(bool paused) { gPaused = paused; }
bool OverlayContrast::measuring() { return gEnabled && !gPaused; }

void OverlayContrast::begin(const ContextCaps& caps, int width, int height)
{
    mOpen = false;
    if (mRun && (width != mWidth || height != mHeight)) endRun();
    if (mRun) {
        // The window as the run's last draw left it: nothing else drew since.
        mBefore.swap(mAfter);
        mOpen = true;
        return;
    }
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
    mRun = true;
    mOpen = true;
}

void OverlayContrast::end()
{
    if (!std::exchange(mOpen, false)) return;
    mAfter.resize(mBefore.size());
    if (FrameGrabber::readFrame(*mCaps, mWidth, mHeight, mAfter.data()) != GL_NO_ERROR) {
        unread("the driver refused the read");
        mRun = false;
        mRunPixels.clear();
        return;
    }
    OverlayLegibility::changedPixels(mBefore.data(), mAfter.data(), mWidth, mHeight,
                                     mRunPixels.emplace_back());
}

void OverlayContrast::endRun()
{
    if (!std::exchange(mRun, false)) return;
    // From the run's last draw back, each with what the draws after it changed marked: their
    // pixels are not its surroundings (the text over a shadow pass).
    mLater.assign(size_t(mWidth) * size_t(mHeight), 0);
    const size_t first = mFrame.size();
    mFrame.resize(first + mRunPixels.size());
    for (size_t k = mRunPixels.size(); k-- > 0;) {
        mFrame[first + k] = OverlayLegibility::measure(mRunPixels[k], mAfter.data(), mWidth,
                                                       mHeight, mLater.data());
        for (const uint32_t i : mRunPixels[k])
            mLater[i] = 1;
    }
    mRunPixels.clear();
}

void OverlayContrast::unread(const char* why)
{
    // The frame's list then lacks draws: compare finds the lists differ and judges nothing.
    if (mUnread++ == 0) NPRGL_WARN("a 2D draw could not be measured: %s", why);
}

std::vector<OverlayContrast::Draw> OverlayContrast::takeFrame()
{
    endRun();
    std::vector<Draw> out;
    out.swap(mFrame);
    return out;
}

} // namespace nprgl
