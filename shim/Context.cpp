#include "shim/Context.h"

#include "common/Log.h"
#include "frame/CaptureSession.h"
#include "frame/Compositor.h"
#include "frame/FrameGrabber.h"
#include "frame/FrameReplay.h"
#include "frame/LiveExport.h"
#include "frame/LiveVideo.h"
#include "frame/Recorder.h"
#include "shim/ConfigWatcher.h"
#include "shim/Overlay.h"
#include "shim/OwnGlCalls.h"
#include "shim/RealGl.h"
#include "shim/RecordingDispatch.h"
#include "shim/ThreadState.h"

#include "styles/Presets.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <utility>

namespace nprgl {

namespace {

// OSMesa has no SwapBuffers; a program's glFinish closes its frame (the glFinish itself
// belongs to the frame it closes).
void APIENTRY osmesaFinish()
{
    Context* ctx = tThread.context;
    if (!ctx) return gRealGl.glFinish();
    ctx->finishBelowHook();
    if (ctx->endFrame(false)) {
        GLint w = 0, h = 0;
        gRealWs.OSMesaGetIntegerv(OSMESA_WIDTH, &w);
        gRealWs.OSMesaGetIntegerv(OSMESA_HEIGHT, &h);
        ctx->writeScreenshot(w, h);
    }
}

// See Context::endUnswappedFrame.
void APIENTRY boundedFlush()
{
    Context* ctx = tThread.context;
    if (!ctx) return gRealGl.glFlush();
    ctx->flushBelowHook();
    ctx->endUnswappedFrame();
}

void APIENTRY boundedFinish()
{
    Context* ctx = tThread.context;
    if (!ctx) return gRealGl.glFinish();
    ctx->finishBelowHook();
    ctx->endUnswappedFrame();
}

// GL 3.0 and newer: the extension list one name at a time.
bool hasExtension(const char* name)
{
    GLint count = 0;
    gRealGl.glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const GLubyte* s = gRealGl.glGetStringi(GL_EXTENSIONS, GLuint(i));
        if (s && std::strcmp(reinterpret_cast<const char*>(s), name) == 0) return true;
    }
    return false;
}

GLenum APIENTRY keptGetError()
{
    Context* ctx = tThread.context;
    return ctx ? ctx->programGetError() : gRealGl.glGetError();
}

} // namespace

void Context::hookGetError()
{
    mGetError = mDispatch.glGetError;
    mDispatch.glGetError = &keptGetError;
}

void Context::keepProgramError(GLenum error)
{
    if (mKeptError == GL_NO_ERROR) mKeptError = error;
}

GLenum Context::programGetError()
{
    if (mKeptError == GL_NO_ERROR) return mGetError();
    // What the program raised since the kept error, GL would have dropped.
    OwnGlCalls::drain();
    return std::exchange(mKeptError, GLenum(GL_NO_ERROR));
}

void Context::endUnswappedFrame()
{
    if (!mRecorder || mRecorder->streamBytes() < kUnswappedFrameBytes) return;
    if (!mUnswappedSaid) {
        NPRGL_INFO("context %u: %zu bytes of calls without a swap; its frames end at glFlush or "
                   "glFinish past %zu MiB (a single-buffered window, or a view drawn off screen "
                   "and shown by another context)",
                   mSerial, mRecorder->streamBytes(), kUnswappedFrameBytes >> 20);
        mUnswappedSaid = true;
    }
    if (endFrame(false) && mWidth > 0 && mHeight > 0) writeScreenshot(mWidth, mHeight);
}

Context::Context(WindowSystem ws, const void* handle, uint32_t serial, const Config& config)
    : mConfig(config), mDispatch(gRealGl), mWs(ws), mHandle(handle), mSerial(serial),
      mConfigLook(config.style.chainName() + "|" + config.style.configText()),
      mConfigRules(config.rules)
{
    // Recording to a file wins over a live export (both need the Stream).
    StreamSink* sink = CaptureSession::instance();
    if (!sink) sink = LiveExport::instance();
    // The compositor reads the Stream too (from memory, frame by frame). With a configuration
    // file it is there even for style none, so that a change of the file can style the
    // program without a restart.
    // A replay measuring 2D draws (OverlayContrast) needs it in style none too.
    const bool styled = mConfig.style.chain().front()->create != nullptr ||
                        !mConfig.files.empty() || OverlayContrast::enabled();
    if (sink || styled) {
        mRecorder = std::make_unique<Recorder>(*this, sink);
        installRecording(mDispatch);
    }
    if (styled) {
        mCompositor = std::make_unique<Compositor>(*this, *mRecorder);
        mCompositor->install(mDispatch);
        mCompositor->setRules(mConfig.rules);
    }
    mFinish = mDispatch.glFinish;
    mFlush = mDispatch.glFlush;
    if (ws == WindowSystem::OSMesa) mDispatch.glFinish = &osmesaFinish;
    if (mRecorder) {
        mDispatch.glFlush = &boundedFlush;
        if (ws != WindowSystem::OSMesa) mDispatch.glFinish = &boundedFinish;
    }
    hookGetError();
}

Context::~Context() = default;

void Context::stopStyling()
{
    // Nothing reads the Stream any more unless it is being recorded: calls go straight to
    // the driver again (the table is per context, so other contexts keep their styles).
    if (!mRecorder || mRecorder->hasSink()) return;
    mDispatch = gRealGl;
    mFinish = mDispatch.glFinish;
    mFlush = mDispatch.glFlush;
    if (mWs == WindowSystem::OSMesa) mDispatch.glFinish = &osmesaFinish;
    hookGetError();
}

void Context::release()
{
    if (mCompositor) mCompositor->flush();
}

void Context::setDrawableSize(int width, int height)
{
    mWidth = width;
    mHeight = height;
}

bool Context::recordsToFile() const { return mRecorder && mRecorder->hasSink(); }

void Context::onMakeCurrent()
{
    if (mInitialized) return;
    mInitialized = true;
    queryCaps();
    // A context the styles cannot draw in is passed through from its first call (and said).
    if (mCompositor) mCompositor->checkContext();
}

void Context::queryCaps()
{
    resolveReal();
    const char* version = reinterpret_cast<const char*>(gRealGl.glGetString(GL_VERSION));
    if (!version) return;
    auto text = [](GLenum name) {
        const GLubyte* s = gRealGl.glGetString(name);
        return s ? std::string(reinterpret_cast<const char*>(s)) : std::string();
    };
    mVendor = text(GL_VENDOR);
    mRenderer = text(GL_RENDERER);
    mVersion = version;
    const char* numbers = version;
    if (std::strncmp(version, "OpenGL ES", 9) == 0) {
        mCaps.es = true;
        numbers = std::strpbrk(version, "0123456789");
        if (!numbers) return;
    }
    std::sscanf(numbers, "%d.%d", &mCaps.major, &mCaps.minor);
    // Only what the context's API and version know is asked: a query it does not know would
    // leave the program a GL error (GL_DOUBLEBUFFER on OpenGL ES: GL_INVALID_ENUM).
    if (mCaps.es) {
        // OpenGL ES has no query for it; its window surfaces have a back buffer (an EGL
        // pbuffer has none, and swapping it does nothing to its pixels either way).
        mCaps.doubleBuffered = true;
        NPRGL_DEBUG("context %u: %s", mSerial, version);
        return;
    }
    if (mCaps.atLeast(3, 2)) {
        GLint mask = 0;
        gRealGl.glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
        mCaps.core = (mask & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
    }
    if (mCaps.atLeast(3, 0) && !mCaps.core) {
        // A forward-compatible context, or a 3.1 one without GL_ARB_compatibility, has no
        // fixed-function pipeline either: the styles cannot run there as on a core profile.
        GLint flags = 0;
        gRealGl.glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
        const bool bare31 = mCaps.major == 3 && mCaps.minor == 1;
        mCaps.core = (flags & GL_CONTEXT_FLAG_FORWARD_COMPATIBLE_BIT) != 0 ||
                     (bare31 && !hasExtension("GL_ARB_compatibility"));
    }
    // Asked now, while the default framebuffer is bound (the answer follows the binding).
    GLboolean db = GL_FALSE;
    gRealGl.glGetBooleanv(GL_DOUBLEBUFFER, &db);
    mCaps.doubleBuffered = db == GL_TRUE;
    NPRGL_DEBUG("context %u: %s (%s%s)", mSerial, version, mCaps.core ? "core" : "compatibility",
                mCaps.doubleBuffered ? ", double-buffered" : "");
}

bool Context::endFrame(bool shown)
{
    if (mCompositor) {
        mCompositor->flush();
        mCompositor->endFrameCounts();
        if (shown || mSwapNext) mCompositor->backBufferShown();
    }
    mSwapNext = false;
    followConfig();
    applyKeys();
    ++mFrame;
    if (mRecorder) mRecorder->endFrame(mFrame);
    LiveVideo* video = LiveVideo::instance();
    mVideoFrame = video && video->wants(mSerial) ? video : nullptr;
    return (mConfig.screenshots && mConfig.screenshotFrames.contains(mFrame)) ||
           !mShotNow.empty() || (mRecorder && mRecorder->frameKept()) || mVideoFrame;
}

void Context::pollKeys(_XDisplay* display)
{
    const std::shared_ptr<const Config> config = Config::current();
    if (!mHotkeys.boundTo(display) || mKeysGeneration != config->generation) {
        mHotkeys.bind(config->keys, config->keyLines, display);
        mKeysGeneration = config->generation;
    }
    mActions |= mHotkeys.poll(display);
}

void Context::applyKeys()
{
    if (!mShotNext.empty()) {
        // The fallback pair's second picture is this frame, drawn unstyled.
        mShotNow = std::exchange(mShotNext, std::string());
        if (mCompositor) mCompositor->setEnabled(mShotRestore);
    }
    const uint32_t actions = std::exchange(mActions, 0u);
    if (!actions) return;
    if (actions & Hotkeys::Video) {
        if (LiveVideo* video = LiveVideo::instance()) {
            video->toggle(mSerial);
        } else {
            NPRGL_WARN("video key: no video was asked for (nprgl run --video FILE)");
        }
    }
    if (actions & Hotkeys::Reload) {
        NPRGL_INFO("reload key: reading the configuration again");
        Config::reload();
        followConfig(true);
    }
    if (!mCompositor) {
        NPRGL_WARN("context %u: the hotkeys need a style or a configuration file at start-up",
                   mSerial);
        return;
    }
    if (actions & Hotkeys::Toggle) mCompositor->setEnabled(!mCompositor->enabled());
    if (actions & Hotkeys::Cycle) cycleStyle();
    if (actions & Hotkeys::Screenshot) startScreenshotPair();
    if (actions & Hotkeys::Overlay) {
        if (!mOverlay) makeOverlay();
        mOverlay->setOpen(!mOverlay->open());
    }
}

void Context::cycleStyle()
{
    const std::shared_ptr<const Config> config = Config::current();
    // The default list starts with the configured look, with its values (a chain's name
    // alone would drop them).
    const std::string configured = "(configured)";
    std::vector<std::string> list = config->cycle;
    if (list.empty()) {
        list = {configured,         "preset:cartoon",   "preset:pencil",
                "preset:blueprint", "preset:technical", "preset:newspaper"};
    }
    // An entry's look: the configured one, a chain, or a preset's chain and values.
    auto resolve = [&](const std::string& entry, StyleSettings& settings, std::string& error) {
        if (entry == configured) {
            settings = config->style;
            return true;
        }
        std::string chain = entry, values;
        if (entry.rfind("preset:", 0) == 0 &&
            !Presets::load(entry.substr(7), chain, values, error)) {
            return false;
        }
        return StyleSettings::parse(chain, values, settings, error);
    };
    auto lookOf = [](const StyleSettings& s) { return s.chainName() + "|" + s.configText(); };
    const std::string running = lookOf(mCompositor->settings());
    // From the entry the key chose last, else the one that looks as the running look (the
    // default list starts with it), else from before the first.
    size_t from = list.size();
    for (size_t i = 0; i < list.size(); ++i) {
        StyleSettings settings;
        std::string error;
        if (mCycled.empty() ? resolve(list[i], settings, error) && lookOf(settings) == running
                            : list[i] == mCycled) {
            from = i;
            break;
        }
    }
    // The next entry that changes what is seen: a press that changes nothing looks broken.
    for (size_t step = 1; step <= list.size(); ++step) {
        const size_t next = (from == list.size() ? step - 1 : from + step) % list.size();
        StyleSettings settings;
        std::string error;
        if (!resolve(list[next], settings, error)) {
            NPRGL_ERROR("cycle key: %s", error.c_str());
            return;
        }
        if (lookOf(settings) == running) continue;
        mCycled = list[next];
        NPRGL_INFO("context %u: cycle key: %s", mSerial,
                   mCycled == configured ? settings.chainName().c_str() : mCycled.c_str());
        mCompositor->restyle(settings);
        mCompositor->setEnabled(true);
        return;
    }
}

void Context::startScreenshotPair()
{
    if (!mShotStem.empty() || !mShotNext.empty() || !mRecorder) return; // a pair under way
    const std::shared_ptr<const Config> config = Config::current();
    std::string dir = config->hotkeyScreenshotDir;
    if (dir.empty()) dir = mConfig.screenshotDir;
    if (dir.empty()) {
        const char* home = std::getenv("HOME");
        dir = home && *home ? std::string(home) + "/Pictures/nprgl" : std::string("/tmp");
    }
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec) {
        NPRGL_ERROR("screenshot key: cannot create %s: %s", dir.c_str(), ec.message().c_str());
        return;
    }
    // <program>_<date>_<time>_<ms>: the pair shares the name up to _styled/_unstyled.
    const auto now = std::chrono::system_clock::now();
    const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
    const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                        now.time_since_epoch()).count() % 1000;
    std::tm local{};
    localtime_r(&seconds, &local);
    char stamp[64];
    std::strftime(stamp, sizeof stamp, "%Y%m%d_%H%M%S", &local);
    char tail[16];
    std::snprintf(tail, sizeof tail, "_%03d", int(ms));
    mShotStem = dir + "/" + mConfig.programName + "_" + stamp + tail;
    mShotRestore = mCompositor->enabled();
    mCompositor->setEnabled(true);
    mRecorder->keepNextFrame();
    NPRGL_INFO("context %u: screenshot key: the next frame, styled and unstyled, to %s_*.png",
               mSerial, mShotStem.c_str());
}

void Context::writeScreenshotPair(int width, int height)
{
    std::vector<uint8_t> calls;
    ClientArrayState start;
    const bool whole = mRecorder->takeKeptFrame(calls, start);
    const std::string stem = std::exchange(mShotStem, std::string());
    if (stem.empty()) return;
    FrameGrabber::writeFrame(mCaps, width, height, stem + "_styled.png");
    // The same frame again as the program draws it, over the styled one, in its own context.
    std::string why = "draws nprgl could not follow";
    bool drawn = false;
    if (whole) {
        // The program's calls again: their errors were the program's once, not now.
        OwnGlCalls own;
        drawn = FrameReplay::run(calls.data(), calls.size(), start, mRecorder->clientArrays(),
                                 why);
    }
    if (drawn) {
        FrameGrabber::writeFrame(mCaps, width, height, stem + "_unstyled.png");
        mCompositor->setEnabled(mShotRestore);
        return;
    }
    NPRGL_WARN("context %u: screenshot key: the frame cannot be drawn again unstyled (%s); "
               "the unstyled picture is of the next frame",
               mSerial, why.c_str());
    mShotNext = stem + "_unstyled.png";
    mCompositor->setEnabled(false);
}

void Context::followConfig(bool asked)
{
    if (ConfigWatcher::instance().changed()) {
        NPRGL_DEBUG("a configuration file changed; reading it again");
        Config::reload();
    }
    const std::shared_ptr<const Config> current = Config::current();
    if (current->generation == mConfigGeneration) return;
    mConfigGeneration = current->generation;
    if (!mCompositor) {
        NPRGL_WARN("context %u runs without styles (it started with style none and no "
                   "configuration file); restart the program to style it",
                   mSerial);
        return;
    }
    // A file written with what it had, or a folder made empty: the look is not touched (nor
    // what the overlay or the cycle key made of it), unless the reload key asked for it.
    const std::string look = current->style.chainName() + "|" + current->style.configText();
    const bool same = look == mConfigLook && current->rules == mConfigRules;
    if (same && !asked) {
        NPRGL_DEBUG("context %u: configuration read again: unchanged", mSerial);
        return;
    }
    mConfigLook = look;
    mConfigRules = current->rules;
    mCompositor->restyle(current->style, !same);
    mCompositor->setRules(current->rules);
    if (same) {
        NPRGL_INFO("context %u: configuration unchanged: style %s", mSerial,
                   current->style.chainName().c_str());
    }
}

void Context::writeScreenshot(int width, int height)
{
    writeHotkeyScreenshot(width, height);
    writeFrameScreenshot(width, height);
}

void Context::writeFrameScreenshot(int width, int height)
{
    if (!mConfig.screenshots || !mConfig.screenshotFrames.contains(mFrame)) return;
    char name[64];
    if (mSerial == 1) {
        std::snprintf(name, sizeof name, "_%llu.png", static_cast<unsigned long long>(mFrame));
    } else {
        std::snprintf(name, sizeof name, "_ctx%u_%llu.png", mSerial,
                      static_cast<unsigned long long>(mFrame));
    }
    const std::string path = mConfig.screenshotDir + "/" + mConfig.programName + name;
    FrameGrabber::writeFrame(mCaps, width, height, path);
}

void Context::writeHotkeyScreenshot(int width, int height)
{
    if (LiveVideo* video = std::exchange(mVideoFrame, nullptr)) {
        video->addFrame(mSerial, mFrame, mCaps, width, height);
    }
    if (mRecorder && mRecorder->frameKept()) writeScreenshotPair(width, height);
    if (mShotNow.empty()) return;
    FrameGrabber::writeFrame(mCaps, width, height, mShotNow);
    mShotNow.clear();
}

void Context::makeOverlay()
{
    const std::vector<std::string> files = Config::filePaths(mConfig.programName);
    mOverlay = std::make_unique<Overlay>(mConfig.programName,
                                         files.empty() ? std::string() : files.back());
}

bool Context::overlayOpen() const
{
    return (mOverlay && mOverlay->open()) || (!mOverlayAsked && mConfig.overlayOpen);
}

void Context::drawOverlay(_XDisplay* display, unsigned long window, int width, int height)
{
    if (!mOverlayAsked) {
        mOverlayAsked = true;
        if (mConfig.overlayOpen && mCompositor) {
            makeOverlay();
            mOverlay->setOpen(true);
        }
    }
    if (mOverlay && mCompositor) {
        mOverlay->draw(*mCompositor, display, Window(window), width, height,
                       mCaps.doubleBuffered);
    }
}

} // namespace nprgl
