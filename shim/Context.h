#pragma once

#include "shim/Api.h"

#include <cstdint>
#include <string>

namespace nprgl {

enum class WindowSystem { Glx, Egl, OSMesa };

// What a context can do, read from the driver when it first becomes current.
struct ContextCaps {
    int major = 0;
    int minor = 0;
    bool es = false;
    bool core = false;
    bool doubleBuffered = false;

    bool atLeast(int maj, int min) const { return major > maj || (major == maj && minor >= min); }
};

// nprgl's view of one GL context of the program: created on its first MakeCurrent, it owns
// the dispatch table the thunks use while it is current, and counts frames.
class Context {
public:
    Context(WindowSystem ws, const void* handle, uint32_t serial);

    // Called on every MakeCurrent to this context, after the driver's.
    void onMakeCurrent();
    // The end of a frame: just before SwapBuffers (or glFinish for swap-less OSMesa).
    // Returns true when this frame is to be written as a screenshot; the caller then asks
    // the window system for the size (a server round trip on GLX, so not every frame) and
    // calls writeScreenshot.
    bool endFrame();
    void writeScreenshot(int width, int height);

    const GlDispatch& dispatch() const { return mDispatch; }
    const ContextCaps& caps() const { return mCaps; }
    WindowSystem windowSystem() const { return mWs; }
    const void* handle() const { return mHandle; }
    uint32_t serial() const { return mSerial; }
    uint64_t frame() const { return mFrame; }

private:
    void queryCaps();

    GlDispatch mDispatch;
    ContextCaps mCaps;
    WindowSystem mWs;
    const void* mHandle;
    uint32_t mSerial; // 1 for the program's first context, 2 for the next...
    uint64_t mFrame = 0;
    bool mInitialized = false;
};

} // namespace nprgl
