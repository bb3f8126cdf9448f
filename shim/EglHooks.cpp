#include "shim/Context.h"
#include "shim/ContextRegistry.h"
#include "shim/ProcAddress.h"
#include "shim/RealGl.h"
#include "shim/ThreadState.h"

// EGL: context life and frames, as for GLX.

namespace nprgl::hooks {

namespace {

// eglQuerySurface is not hooked; it is fetched from the driver once.
void surfaceSize(EGLDisplay dpy, EGLSurface surface, EGLint& width, EGLint& height)
{
    using QuerySurface = EGLBoolean (*)(EGLDisplay, EGLSurface, EGLint, EGLint*);
    static auto query = reinterpret_cast<QuerySurface>(realProcAddress("eglQuerySurface"));
    width = height = 0;
    if (!query || surface == EGL_NO_SURFACE) return;
    if (!query(dpy, surface, EGL_WIDTH, &width) || !query(dpy, surface, EGL_HEIGHT, &height))
        width = height = 0;
}

} // namespace

EGLBoolean eglMakeCurrent(EGLDisplay dpy, EGLSurface draw, EGLSurface read, EGLContext ctx)
{
    if (Context* current = tThread.context) current->release();
    EGLBoolean ok = gRealWs.eglMakeCurrent(dpy, draw, read, ctx);
    if (ok) {
        ContextRegistry::instance().makeCurrent(WindowSystem::Egl,
                                                ctx == EGL_NO_CONTEXT ? nullptr : ctx);
        // The size goes into capture files (a surfaceless context has none: the capture
        // takes the viewport instead, see CaptureSession).
        if (Context* c = tThread.context; c && c->recorder()) {
            EGLint width = 0, height = 0;
            surfaceSize(dpy, draw, width, height);
            c->setDrawableSize(width, height);
        }
    }
    return ok;
}

EGLBoolean eglDestroyContext(EGLDisplay dpy, EGLContext ctx)
{
    EGLBoolean ok = gRealWs.eglDestroyContext(dpy, ctx);
    if (ok) ContextRegistry::instance().destroy(WindowSystem::Egl, ctx);
    return ok;
}

EGLBoolean eglSwapBuffers(EGLDisplay dpy, EGLSurface surface)
{
    Context* ctx = tThread.context;
    if (ctx && ctx->windowSystem() == WindowSystem::Egl) {
        // The surface's size while recording to a file (its header) or for a screenshot.
        EGLint width = 0, height = 0;
        const bool recording = ctx->recordsToFile();
        if (recording) {
            surfaceSize(dpy, surface, width, height);
            if (width > 0 && height > 0) ctx->setDrawableSize(width, height);
        }
        if (ctx->endFrame(true)) {
            if (!recording) surfaceSize(dpy, surface, width, height);
            ctx->writeScreenshot(width, height);
        }
    }
    return gRealWs.eglSwapBuffers(dpy, surface);
}

__eglMustCastToProperFunctionPointerType eglGetProcAddress(const char* name)
{
    if (void* thunk = ourProcAddress(name)) {
        return reinterpret_cast<__eglMustCastToProperFunctionPointerType>(thunk);
    }
    return gRealWs.eglGetProcAddress(name);
}

} // namespace nprgl::hooks
