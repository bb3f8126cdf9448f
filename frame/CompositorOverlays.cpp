// The compositor's measure of the 2D draws it leaves (a replay's --overlays).
#include "frame/Compositor.h"

#include "shim/Context.h"
#include "shim/RealGl.h"

#include <utility>

namespace nprgl {

bool Compositor::overlayMeasurable()
{
    if (!OverlayContrast::measuring() || mPhase != Phase::Ready || mBroken) return false;
    // Without styles placeDraw does not follow the stream: the tracker is brought up to date
    // here (a native replay's figures are taken in style none).
    syncStream();
    if (mTracker.is3D() || !mTracker.executing() || mTracker.compiling() ||
        mTracker.renderMode() != GL_RENDER) {
        return false;
    }
    GLint framebuffer = 0;
    gRealGl.glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    return framebuffer == 0;
}

void Compositor::overlayPlaced()
{
    if (OverlayContrast::measuring() && !overlayMeasurable()) mOverlays.endRun();
}

void Compositor::overlayBegin()
{
    mMeasuring = false;
    if (!OverlayContrast::measuring()) return;
    if (!overlayMeasurable()) {
        mOverlays.endRun();
        return;
    }
    mOverlays.begin(mContext.caps(), mContext.drawableWidth(), mContext.drawableHeight());
    mMeasuring = true;
}

void Compositor::overlayEnd()
{
    if (std::exchange(mMeasuring, false)) mOverlays.end();
}

} // namespace nprgl
