// Two threads, each with its own window and GLX context on one Display (XInitThreads), draw
// lit 3D shapes at the same time for a number of frames. Each reads its last frame back before
// the swap (after nprgl styled it) and writes it as <dir>/thread<N>.png.
//
// With exit-mid-frame, the second thread draws on without waiting for the first and, after
// its frames, starts one more and stops there, its context still current (a render thread the
// program never stops); the program prints ok and calls exit() once the first thread is done.
//
// Usage: probe_glx_threads FRAMES DIR [exit-mid-frame]
#include "common/PngImage.h"

#include <GL/gl.h>
#include <GL/glx.h>
#include <X11/Xlib.h>
#include <atomic>
#include <barrier>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <unistd.h>

namespace {

constexpr int kWidth = 128;
constexpr int kHeight = 96;
constexpr float kPi = 3.14159265f;

struct View {
    ::Window window = 0;
    GLXContext context = nullptr;
};

// A torus of quads with per-vertex normals, in immediate mode.
void drawTorus(float major, float minor, int rings, int sides)
{
    for (int i = 0; i < rings; ++i) {
        glBegin(GL_QUAD_STRIP);
        for (int j = 0; j <= sides; ++j) {
            for (int k = 1; k >= 0; --k) {
                float u = 2 * kPi * float(i + k) / float(rings);
                float v = 2 * kPi * float(j) / float(sides);
                float nx = std::cos(u) * std::cos(v), ny = std::sin(u) * std::cos(v);
                float nz = std::sin(v);
                glNormal3f(nx, ny, nz);
                glVertex3f(std::cos(u) * major + nx * minor, std::sin(u) * major + ny * minor,
                           nz * minor);
            }
        }
        glEnd();
    }
}

// A box of six lit quads.
void drawBox(float s)
{
    static const float kFaces[6][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    glBegin(GL_QUADS);
    for (const auto& n : kFaces) {
        // Two axes spanning the face; a x b = n, so the quad winds counter-clockwise from
        // outside.
        float a[3] = {n[2], n[0], n[1]};
        float b[3] = {n[1] * a[2] - n[2] * a[1], n[2] * a[0] - n[0] * a[2],
                      n[0] * a[1] - n[1] * a[0]};
        glNormal3fv(n);
        for (int c = 0; c < 4; ++c) {
            float sa = (c == 0 || c == 3) ? -1.0f : 1.0f, sb = c < 2 ? -1.0f : 1.0f;
            glVertex3f(s * (n[0] + sa * a[0] + sb * b[0]), s * (n[1] + sa * a[1] + sb * b[1]),
                       s * (n[2] + sa * a[2] + sb * b[2]));
        }
    }
    glEnd();
}

void drawFrame(int thread, int frame)
{
    glViewport(0, 0, kWidth, kHeight);
    glClearColor(0.2f, 0.25f, 0.3f, 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_LIGHTING);
    glEnable(GL_LIGHT0);
    glEnable(GL_NORMALIZE);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(-0.67, 0.67, -0.5, 0.5, 1, 20);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    const float light[] = {2, 3, 4, 0};
    glLightfv(GL_LIGHT0, GL_POSITION, light);
    glTranslatef(0, 0, -5);
    glRotatef(30.0f + 10.0f * float(frame), 1, 0.6f, 0.2f);
    const float red[] = {0.9f, 0.2f, 0.1f, 1}, blue[] = {0.1f, 0.4f, 0.9f, 1};
    glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE, thread == 0 ? red : blue);
    if (thread == 0) {
        drawTorus(1.2f, 0.45f, 24, 12);
    } else {
        drawBox(1.0f);
    }
}

bool writeBackBuffer(const std::string& path)
{
    nprgl::PngImage image;
    image.width = kWidth;
    image.height = kHeight;
    image.rgba.resize(size_t(kWidth) * kHeight * 4);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kWidth, kHeight, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
    image.flipRows();
    std::string error;
    if (!image.write(path, error)) {
        std::fprintf(stderr, "probe_glx_threads: %s\n", error.c_str());
        return false;
    }
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    const bool exitMidFrame = argc == 4 && std::string(argv[3]) == "exit-mid-frame";
    if (argc != 3 && !exitMidFrame) {
        std::fprintf(stderr, "usage: probe_glx_threads FRAMES DIR [exit-mid-frame]\n");
        return 2;
    }
    const int frames = std::atoi(argv[1]);
    const std::string dir = argv[2];
    if (!XInitThreads()) return 3;
    Display* dpy = XOpenDisplay(nullptr);
    // A busy Xvfb can refuse a connection for a moment.
    for (int attempt = 0; !dpy && attempt < 20 && std::getenv("DISPLAY"); ++attempt) {
        usleep(100000);
        dpy = XOpenDisplay(nullptr);
    }
    if (!dpy) return 4;
    int attributes[] = {GLX_RGBA, GLX_DOUBLEBUFFER, GLX_RED_SIZE, 8, GLX_GREEN_SIZE, 8,
                        GLX_BLUE_SIZE, 8, GLX_DEPTH_SIZE, 24, None};
    XVisualInfo* visual = glXChooseVisual(dpy, DefaultScreen(dpy), attributes);
    if (!visual) return 5;
    ::Window root = DefaultRootWindow(dpy);
    Colormap colormap = XCreateColormap(dpy, root, visual->visual, AllocNone);
    View windows[2];
    for (int i = 0; i < 2; ++i) {
        XSetWindowAttributes wa{};
        wa.colormap = colormap;
        wa.event_mask = StructureNotifyMask;
        windows[i].window = XCreateWindow(dpy, root, i * (kWidth + 10), 0, kWidth, kHeight, 0,
                                          visual->depth, InputOutput, visual->visual,
                                          CWColormap | CWEventMask, &wa);
        windows[i].context = glXCreateContext(dpy, visual, nullptr, True);
        if (!windows[i].context) return 6;
        XMapWindow(dpy, windows[i].window);
        XEvent event;
        do {
            XWindowEvent(dpy, windows[i].window, StructureNotifyMask, &event);
        } while (event.type != MapNotify);
    }
    XFree(visual);

    // Both threads start each frame together, so their GL calls and frame ends overlap.
    std::barrier sync(exitMidFrame ? 1 : 2);
    bool ok[2] = {false, false};
    std::atomic<bool> stopped{false}; // exit-mid-frame: the second thread is in its last frame
    auto run = [&](int t) {
        if (!glXMakeCurrent(dpy, windows[t].window, windows[t].context)) {
            sync.arrive_and_drop(); // the other thread must not wait for this one
            return;
        }
        bool written = true;
        for (int frame = 1; frame <= frames; ++frame) {
            if (!exitMidFrame) sync.arrive_and_wait();
            drawFrame(t, frame);
            if (frame == frames) {
                written = writeBackBuffer(dir + "/thread" + std::to_string(t) + ".png");
            }
            glXSwapBuffers(dpy, windows[t].window);
        }
        if (exitMidFrame && t == 1) {
            drawFrame(t, frames + 1);
            stopped = true;
            for (;;) pause(); // until the process exits
        }
        glXMakeCurrent(dpy, None, nullptr);
        ok[t] = written;
    };
    std::thread a(run, 0), b(run, 1);
    a.join();
    if (exitMidFrame) {
        while (!stopped) usleep(1000);
        std::printf(ok[0] ? "ok\n" : "failed\n");
        std::fflush(stdout);
        std::exit(ok[0] ? 0 : 7); // the second thread still in its frame
    }
    b.join();
    for (View& w : windows) {
        glXDestroyContext(dpy, w.context);
        XDestroyWindow(dpy, w.window);
    }
    XFreeColormap(dpy, colormap);
    XCloseDisplay(dpy);
    if (!ok[0] || !ok[1]) return 7;
    std::printf("ok\n");
    return 0;
}
