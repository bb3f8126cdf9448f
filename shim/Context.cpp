#include "shim/Context.h"

#include "common/Log.h"
#include "frame/CaptureSession.h"
#include "frame/Compositor.h"
#include "frame/FrameGrabber.h"
#include "frame/LiveExport.h"
#include "frame/Recorder.h"
#include "shim/ConfigWatcher.h"
#include "shim/RealGl.h"
#include "shim/RecordingDispatch.h"
#include "shim/ThreadState.h"

#include <cstdio>
#include <cstring>

namespace nprgl {

namespace {

// OSMesa has no SwapBuffers; a program's glFinish closes its frame (the glFinish itself
// belongs to the frame it closes).
void APIENTRY osmesaFinish()
{
    Context* ctx = tThread.context;
    if (!ctx) return gRealGl.glFinish();
    ctx->finishBelowHook();
    if (ctx->endFrame()) {
        GLint w = 0, h = 0;
        gRealWs.OSMesaGetIntegerv(OSMESA_WIDTH, &w);
        gRealWs.OSMesaGetIntegerv(OSMESA_HEIGHT, &h);
        ctx->writeScreenshot(w, h);
    }
}

} // namespace

Context::Context(WindowSystem ws, const void* handle, uint32_t serial, const Config& config)
    : mConfig(config), mDispatch(gRealGl), mWs(ws), mHandle(handle), mSerial(serial)
{
    // Recording to a file wins over a live export (both need the Stream).
    StreamSink* sink = CaptureSession::instance();
    if (!sink) sink = LiveExport::instance();
    // The compositor reads the Stream too (from memory, frame by frame). With a configuration
    // file it is there even for style none, so that a change of the file can style the
    // program without a restart.
    const bool styled =
        mConfig.style.chain().front()->create != nullptr || !mConfig.files.empty();
    if (sink || styled) {
        mRecorder = std::make_unique<Recorder>(*this, sink);
        installRecording(mDispatch);
    }
    if (styled) {
        mCompositor = std::make_unique<Compositor>(*this, *mRecorder);
        mCompositor->install(mDispatch);
    }
    mFinish = mDispatch.glFinish;
    if (ws == WindowSystem::OSMesa) mDispatch.glFinish = &osmesaFinish;
}

Context::~Context() = default;

void Context::stopStyling()
{
    // Nothing reads the Stream any more unless it is being recorded: calls go straight to
    // the driver again (the table is per context, so other contexts keep their styles).
    if (!mRecorder || mRecorder->hasSink()) return;
    mDispatch = gRealGl;
    mFinish = mDispatch.glFinish;
    if (mWs == WindowSystem::OSMesa) mDispatch.glFinish = &osmesaFinish;
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

void Context::onMakeCurrent()
{
    if (mInitialized) return;
    mInitialized = true;
    queryCaps();
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
    if (!mCaps.es && mCaps.atLeast(3, 2)) {
        GLint mask = 0;
        gRealGl.glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
        mCaps.core = (mask & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
    }
    // Asked now, while the default framebuffer is bound (the answer follows the binding).
    GLboolean db = GL_FALSE;
    gRealGl.glGetBooleanv(GL_DOUBLEBUFFER, &db);
    mCaps.doubleBuffered = db == GL_TRUE;
    NPRGL_DEBUG("context %u: %s (%s%s)", mSerial, version, mCaps.core ? "core" : "compatibility",
                mCaps.doubleBuffered ? ", double-buffered" : "");
}

bool Context::endFrame()
{
    if (mCompositor) mCompositor->flush();
    followConfig();
    ++mFrame;
    if (mRecorder) mRecorder->endFrame(mFrame);
    return mConfig.screenshots && mConfig.screenshotFrames.contains(mFrame);
}

void Context::followConfig()
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
    mCompositor->restyle(current->style);
}

void Context::writeScreenshot(int width, int height)
{
    char name[64];
    if (mSerial == 1) {
        std::snprintf(name, sizeof name, "_%llu.png", static_cast<unsigned long long>(mFrame));
    } else {
        std::snprintf(name, sizeof name, "_ctx%u_%llu.png", mSerial,
                      static_cast<unsigned long long>(mFrame));
    }
    std::string path = mConfig.screenshotDir + "/" + mConfig.programName + name;
    FrameGrabber::writeFrame(mCaps, width, height, path);
}

} // namespace nprgl
