#include "shim/Context.h"
#include "shim/ContextRegistry.h"
#include "shim/GlxWindows.h"
#include "shim/ProcAddress.h"
#include "shim/RealGl.h"
#include "shim/ThreadState.h"

// GLX: context life and frames. Every hook calls the driver first (or last, for the swap) and
// never changes what the driver answers.

namespace nprgl::hooks {

GLXContext glXCreateContext(Display* dpy, XVisualInfo* vis, GLXContext share, Bool direct)
{
    return gRealWs.glXCreateContext(dpy, vis, share, direct);
}

GLXContext glXCreateNewContext(Display* dpy, GLXFBConfig config, int renderType,
                               GLXContext share, Bool direct)
{
    return gRealWs.glXCreateNewContext(dpy, config, renderType, share, direct);
}

GLXContext glXCreateContextAttribsARB(Display* dpy, GLXFBConfig config, GLXContext share,
                                      Bool direct, const int* attribs)
{
    return gRealWs.glXCreateContextAttribsARB(dpy, config, share, direct, attribs);
}

void glXDestroyContext(Display* dpy, GLXContext ctx)
{
    gRealWs.glXDestroyContext(dpy, ctx);
    ContextRegistry::instance().destroy(WindowSystem::Glx, ctx);
}

GLXWindow glXCreateWindow(Display* dpy, GLXFBConfig config, Window win, const int* attribs)
{
    const GLXWindow made = gRealWs.glXCreateWindow(dpy, config, win, attribs);
    if (made) GlxWindows::instance().add(made, win);
    return made;
}

void glXDestroyWindow(Display* dpy, GLXWindow win)
{
    gRealWs.glXDestroyWindow(dpy, win);
    GlxWindows::instance().remove(win);
}

namespace {

void onMakeCurrent(Display* dpy, GLXDrawable draw, GLXContext ctx)
{
    ContextRegistry::instance().makeCurrent(WindowSystem::Glx, ctx);
    // The size goes into capture files; asking costs a server round trip, so only then.
    if (Context* c = tThread.context; c && c->recorder() && draw) {
        unsigned width = 0, height = 0;
        gRealWs.glXQueryDrawable(dpy, draw, GLX_WIDTH, &width);
        gRealWs.glXQueryDrawable(dpy, draw, GLX_HEIGHT, &height);
        c->setDrawableSize(int(width), int(height));
    }
}

} // namespace

Bool glXMakeCurrent(Display* dpy, GLXDrawable drawable, GLXContext ctx)
{
    if (Context* current = tThread.context) current->release();
    Bool ok = gRealWs.glXMakeCurrent(dpy, drawable, ctx);
    if (ok) onMakeCurrent(dpy, drawable, ctx);
    return ok;
}

Bool glXMakeContextCurrent(Display* dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx)
{
    if (Context* current = tThread.context) current->release();
    Bool ok = gRealWs.glXMakeContextCurrent(dpy, draw, read, ctx);
    if (ok) onMakeCurrent(dpy, draw, ctx);
    return ok;
}

void glXSwapBuffers(Display* dpy, GLXDrawable drawable)
{
    Context* ctx = tThread.context;
    const bool ours = ctx && ctx->windowSystem() == WindowSystem::Glx &&
                      gRealWs.glXGetCurrentDrawable() == drawable;
    if (ours) {
        ctx->pollKeys(dpy);
        // The drawable's size is a server round trip: asked at most once, and only while
        // recording to a file (its header), for a screenshot or for the overlay.
        unsigned width = 0, height = 0;
        bool asked = false;
        auto askSize = [&] {
            if (asked) return;
            asked = true;
            gRealWs.glXQueryDrawable(dpy, drawable, GLX_WIDTH, &width);
            gRealWs.glXQueryDrawable(dpy, drawable, GLX_HEIGHT, &height);
        };
        if (ctx->recordsToFile()) {
            askSize();
            if (width > 0 && height > 0) ctx->setDrawableSize(int(width), int(height));
        }
        // Swapping a single-buffered drawable shows nothing and keeps its pixels.
        const bool shots = ctx->endFrame(ctx->caps().doubleBuffered);
        if (shots || ctx->overlayOpen()) askSize();
        // The hotkey's pair without the overlay; the configured frames as the window shows.
        if (shots) ctx->writeHotkeyScreenshot(int(width), int(height));
        ctx->drawOverlay(dpy, GlxWindows::instance().windowOf(drawable), int(width),
                         int(height));
        if (shots) ctx->writeFrameScreenshot(int(width), int(height));
    }
    gRealWs.glXSwapBuffers(dpy, drawable);
}

__GLXextFuncPtr glXGetProcAddress(const GLubyte* name)
{
    if (void* thunk = ourProcAddress(reinterpret_cast<const char*>(name))) {
        return reinterpret_cast<__GLXextFuncPtr>(thunk);
    }
    return gRealWs.glXGetProcAddress(name);
}

__GLXextFuncPtr glXGetProcAddressARB(const GLubyte* name)
{
    if (void* thunk = ourProcAddress(reinterpret_cast<const char*>(name))) {
        return reinterpret_cast<__GLXextFuncPtr>(thunk);
    }
    return gRealWs.glXGetProcAddressARB(name);
}

} // namespace nprgl::hooks
