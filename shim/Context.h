#pragma once

#include "shim/Api.h"
#include "shim/Config.h"
#include "shim/Hotkeys.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>

namespace nprgl {

class Compositor;
class LiveVideo;
class Overlay;
class Recorder;

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

// Calls held without a frame's end past which a glFlush or glFinish ends one
// (Context::endUnswappedFrame): far above what a frame of a real program holds.
inline constexpr size_t kUnswappedFrameBytes = size_t(32) << 20;

// nprgl's view of one GL context of the program: created on its first MakeCurrent, it owns
// the dispatch table the thunks use while it is current, and counts frames.
class Context {
public:
    Context(WindowSystem ws, const void* handle, uint32_t serial, const Config& config);
    ~Context();

    // Called on every MakeCurrent to this context, after the driver's.
    void onMakeCurrent();
    // The end of a frame: just before SwapBuffers (or glFinish for swap-less OSMesa).
    // `shown`: a back buffer is swapped, so its contents are undefined afterwards.
    // Returns true when this frame is to be written as a screenshot; the caller then asks
    // the window system for the size (a server round trip on GLX, so not every frame) and
    // calls writeScreenshot.
    bool endFrame(bool shown);
    // A replay's next frame end is the recorded program's swap (OSMesa has none).
    void swapAtNextFrameEnd() { mSwapNext = true; }
    void writeScreenshot(int width, int height);
    // writeScreenshot's two halves, for a window system with the overlay between them: the
    // hotkey's picture (without the overlay) and the configured frames' (as shown).
    void writeHotkeyScreenshot(int width, int height);
    void writeFrameScreenshot(int width, int height);
    // Just before the swap, after the screenshots: the overlay, when it is open.
    bool overlayOpen() const;
    void drawOverlay(_XDisplay* display, unsigned long window, int width, int height);
    // Before endFrame on a window system with a keyboard: reads the hotkeys' state.
    void pollKeys(_XDisplay* display);
    // The size of the drawable it was last made current with or, while recording to a file,
    // shown at the last swap (0 when not known).
    void setDrawableSize(int width, int height);
    // Whether frames go to a capture file: the swap hooks then ask the drawable's size (a
    // server round trip), which the file's header takes from its first frame.
    bool recordsToFile() const;

    // The program is about to make another context (or none) current: draw what is held.
    void release();
    // The compositor cannot run here (core profile, OpenGL ES, old GL): back to plain
    // forwarding.
    void stopStyling();

    // A GL error the program raised before nprgl's own calls took it from the driver
    // (OwnGlCalls): the program's next glGetError answers it. GL keeps the first error until
    // it is asked for and drops those raised meanwhile, and so does this.
    void keepProgramError(GLenum error);
    // The program's glGetError: the error kept for it, else the driver's.
    GLenum programGetError();

    // Null unless the process records (NPRGL_RECORD, NPRGL_EXPORT) or a style is active.
    Recorder* recorder() const { return mRecorder.get(); }
    // Null when the style is none.
    Compositor* compositor() const { return mCompositor.get(); }
    // The glFinish and glFlush below nprgl's frame hooks (the recording ones or the driver's).
    void finishBelowHook() const { mFinish(); }
    void flushBelowHook() const { mFlush(); }
    // A glFlush or glFinish of a context whose calls since its last frame passed
    // kUnswappedFrameBytes ends a frame (not shown): a context that never swaps (a
    // single-buffered window, an off-screen view another context shows) would otherwise
    // hold its calls for ever.
    void endUnswappedFrame();

    // The threads it is current on (ContextRegistry keeps the count): at exit its run's
    // counts are read as they stand only where no other thread may be drawing with it.
    void noteCurrent(int delta) { mThreadsCurrent.fetch_add(delta, std::memory_order_acq_rel); }
    int threadsCurrent() const { return mThreadsCurrent.load(std::memory_order_acquire); }

    const GlDispatch& dispatch() const { return mDispatch; }
    const ContextCaps& caps() const { return mCaps; }
    WindowSystem windowSystem() const { return mWs; }
    const void* handle() const { return mHandle; }
    uint32_t serial() const { return mSerial; }
    const Config& config() const { return mConfig; }
    uint64_t frame() const { return mFrame; }
    const std::string& vendor() const { return mVendor; }
    const std::string& renderer() const { return mRenderer; }
    const std::string& version() const { return mVersion; }
    int drawableWidth() const { return mWidth; }
    int drawableHeight() const { return mHeight; }

private:
    void queryCaps();
    // The dispatch's glGetError answers the program's kept error first.
    void hookGetError();
    // At a frame end: picks up a changed configuration file (the next frame runs it).
    // `asked`: by the reload key, which applies the files' look even when unchanged.
    void followConfig(bool asked = false);
    // At a frame end: does what the hotkeys pressed since the last one ask.
    void applyKeys();
    void cycleStyle();
    void startScreenshotPair();
    void writeScreenshotPair(int width, int height);
    void makeOverlay();

    const Config& mConfig; // the process's (Config::process), which outlives every context
    GlDispatch mDispatch;
    void(APIENTRY* mFinish)() = nullptr;
    void(APIENTRY* mFlush)() = nullptr;
    GLenum(APIENTRY* mGetError)() = nullptr; // below the dispatch's glGetError hook
    GLenum mKeptError = GL_NO_ERROR;         // keepProgramError
    bool mUnswappedSaid = false;
    std::atomic<int> mThreadsCurrent{0};
    std::unique_ptr<Recorder> mRecorder;
    std::unique_ptr<Compositor> mCompositor;
    std::string mVendor, mRenderer, mVersion;
    int mWidth = 0, mHeight = 0;
    ContextCaps mCaps;
    WindowSystem mWs;
    const void* mHandle;
    uint32_t mSerial; // 1 for the program's first context, 2 for the next...
    uint64_t mFrame = 0;
    uint64_t mConfigGeneration = 0; // the Config::current() generation this context runs
    std::string mConfigLook;        // its style, "chain|values", and its rules
    LeaveRules mConfigRules;
    Hotkeys mHotkeys;
    uint64_t mKeysGeneration = UINT64_MAX; // the configuration generation the keys are from
    uint32_t mActions = 0;                 // pressed since the last frame end
    // The screenshot key: the next frame is drawn styled and kept (Recorder::keepNextFrame),
    // written at its swap, then drawn again unstyled from its calls (FrameReplay) and
    // written: mShotStem_styled.png and _unstyled.png. Where it cannot be drawn again, the
    // unstyled picture is of the frame after it (mShotNext, then mShotNow at its swap).
    std::string mShotStem;
    // The video this frame goes to (at writeHotkeyScreenshot), when it goes to one.
    LiveVideo* mVideoFrame = nullptr;
    std::string mShotNow;    // a hotkey screenshot of this frame, written at this swap
    std::string mShotNext;   // the fallback's unstyled picture, of the next frame
    bool mShotRestore = true; // styling on or off after the pair
    std::string mCycled;      // the cycle list's entry running now
    std::unique_ptr<Overlay> mOverlay; // made when first opened
    bool mOverlayAsked = false;        // overlay=open at start-up was looked at
    bool mInitialized = false;
    bool mSwapNext = false; // swapAtNextFrameEnd
};

} // namespace nprgl
