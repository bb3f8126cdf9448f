#include "GlxWindow.h"

#include <algorithm>
#include <cstdlib>
#include <unistd.h>

#include "Readback.h"

#include <X11/Xutil.h>
#include <X11/extensions/XTest.h>
#include <X11/keysym.h>

namespace demo {

GlxWindow::~GlxWindow()
{
    if (display_ == nullptr) {
        return;
    }
    if (context_ != nullptr) {
        gl_.glXMakeCurrent(display_, None, nullptr);
        gl_.glXDestroyContext(display_, context_);
    }
    if (window_ != 0) {
        XDestroyWindow(display_, window_);
    }
    if (colormap_ != 0) {
        XFreeColormap(display_, colormap_);
    }
    XCloseDisplay(display_);
}

bool GlxWindow::open(const Options& options, std::string& error)
{
    width_ = options.width;
    height_ = options.height;
    // A busy X server (Xvfb serving several test programs) can refuse a connection for a
    // moment; a few short retries make the demos dependable in CI.
    display_ = XOpenDisplay(nullptr);
    for (int attempt = 0; !display_ && attempt < 20 && std::getenv("DISPLAY"); ++attempt) {
        usleep(100000);
        display_ = XOpenDisplay(nullptr);
    }
    if (display_ == nullptr) {
        error = "cannot open X display (is DISPLAY set?)";
        return false;
    }
    int screen = DefaultScreen(display_);
    int attributes[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8,
                        GLX_BLUE_SIZE, 8, GLX_DEPTH_SIZE, 24, None};
    XVisualInfo* visual = gl_.glXChooseVisual(display_, screen, attributes);
    if (visual == nullptr) {
        error = "no double-buffered RGB visual with a 24-bit depth buffer";
        return false;
    }

    Window root = RootWindow(display_, screen);
    colormap_ = XCreateColormap(display_, root, visual->visual, AllocNone);
    XSetWindowAttributes windowAttributes{};
    windowAttributes.colormap = colormap_;
    windowAttributes.border_pixel = 0;
    windowAttributes.event_mask = KeyPressMask | StructureNotifyMask | ExposureMask;
    window_ = XCreateWindow(display_, root, 0, 0, width_, height_, 0, visual->depth, InputOutput,
                            visual->visual, CWColormap | CWBorderPixel | CWEventMask,
                            &windowAttributes);

    fixSize();
    XStoreName(display_, window_, options.appName.c_str());
    deleteAtom_ = XInternAtom(display_, "WM_DELETE_WINDOW", False);
    XSetWMProtocols(display_, window_, &deleteAtom_, 1);

    context_ = gl_.glXCreateContext(display_, visual, nullptr, True);
    XFree(visual);
    if (context_ == nullptr) {
        error = "glXCreateContext failed";
        return false;
    }
    XMapWindow(display_, window_);
    XEvent event;
    do {
        XWindowEvent(display_, window_, StructureNotifyMask, &event);
    } while (event.type != MapNotify);

    if (!gl_.glXMakeCurrent(display_, window_, context_)) {
        error = "glXMakeCurrent failed";
        return false;
    }
    return true;
}

bool GlxWindow::processEvents()
{
    bool keepRunning = true;
    while (XPending(display_) > 0) {
        XEvent event;
        XNextEvent(display_, &event);
        if (event.type == KeyPress) {
            KeySym key = XLookupKeysym(&event.xkey, 0);
            if (key == XK_Escape || key == XK_q) {
                keepRunning = false;
            }
        } else if (event.type == ClientMessage
                   && static_cast<Atom>(event.xclient.data.l[0]) == deleteAtom_) {
            keepRunning = false;
        } else if (event.type == DestroyNotify) {
            keepRunning = false;
        }
    }
    return keepRunning;
}

void GlxWindow::readPixels(Image& image)
{
    GLint oldReadBuffer = GL_BACK;
    gl_.getIntegerv(GL_READ_BUFFER, &oldReadBuffer);
    gl_.readBuffer(GL_BACK);
    readFramebuffer(gl_, width_, height_, image);
    gl_.readBuffer(static_cast<GLenum>(oldReadBuffer));
}

void GlxWindow::fixSize()
{
    // A fixed size keeps the pictures independent of the window manager.
    XSizeHints hints{};
    hints.flags = PMinSize | PMaxSize;
    hints.min_width = hints.max_width = width_;
    hints.min_height = hints.max_height = height_;
    XSetWMNormalHints(display_, window_, &hints);
}

void GlxWindow::pressKeys(const std::string& keys, bool down)
{
    // XTEST, as the X server sees a user's keys (nprgl polls the keyboard state at the swap).
    for (size_t at = 0; at <= keys.size();) {
        const size_t plus = std::min(keys.find('+', at), keys.size());
        const KeySym sym = XStringToKeysym(keys.substr(at, plus - at).c_str());
        if (sym != NoSymbol) {
            XTestFakeKeyEvent(display_, XKeysymToKeycode(display_, sym), down ? True : False,
                              CurrentTime);
        }
        at = plus + 1;
    }
    XSync(display_, False);
}

void GlxWindow::resize(int width, int height)
{
    width_ = width;
    height_ = height;
    fixSize();
    XResizeWindow(display_, window_, unsigned(width), unsigned(height));
    XEvent event;
    do {
        XWindowEvent(display_, window_, StructureNotifyMask, &event);
    } while (event.type != ConfigureNotify || event.xconfigure.width != width ||
             event.xconfigure.height != height);
}

void GlxWindow::present()
{
    gl_.glXSwapBuffers(display_, window_);
}

} // namespace demo
