// A GLX window drawing the lit, turning cube for a number of frames, pressing key
// combinations with XTEST at given frames (--press K Shift_R+F9: down at the start of frame K,
// up at the start of frame K+1; --hold K L F9: down at the start of frame K, up at the start
// of frame L; --tap K F9: down and up again at the start of frame K, between two swaps, as a
// tap shorter than a slow frame is), moving the pointer (--pointer K X Y, window pixels) and
// pressing or letting go of the left button (--button K down|up) at the start of frame K,
// as a user would: the hotkey and overlay tests, counted in frames. --textured adds a
// textured poster in front of the cube, in the window's lower right corner; --decal draws it
// with a polygon offset (a decal, for state rules).
#include "tests/probes/ProbeCube.h"
#include "tests/probes/ProbeTexture.h"

#include <GL/glx.h>
#include <X11/Xlib.h>
#include <X11/extensions/XTest.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace {


std::vector<KeyCode> keycodes(Display* dpy, const std::string& combination)
{
    std::vector<KeyCode> codes;
    size_t at = 0;
    while (at <= combination.size()) {
        const size_t plus = combination.find('+', at);
        const std::string name = combination.substr(at, plus - at);
        const KeySym sym = XStringToKeysym(name.c_str());
        if (sym != NoSymbol) codes.push_back(XKeysymToKeycode(dpy, sym));
        if (plus == std::string::npos) break;
        at = plus + 1;
    }
    return codes;
}

void setKeys(Display* dpy, const std::vector<KeyCode>& codes, bool down)
{
    for (KeyCode code : codes) XTestFakeKeyEvent(dpy, code, down ? True : False, CurrentTime);
    XSync(dpy, False);
}

// A 64x64 checkerboard of two blues, generated.
GLuint makePosterTexture()
{
    std::vector<uint8_t> texels(64 * 64 * 3);
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            const bool dark = ((x / 8) + (y / 8)) % 2 != 0;
            uint8_t* t = &texels[size_t(y * 64 + x) * 3];
            t[0] = dark ? 30 : 120;
            t[1] = dark ? 60 : 170;
            t[2] = dark ? 140 : 240;
        }
    }
    return nprgl::probes::uploadRgbTexture(texels, 64, GL_NEAREST);
}

// In front of the cube (z = -2.2; the cube's nearest corner is at -2.27), unlit, textured.
void drawPoster(GLuint texture, bool decal)
{
    if (decal) {
        glEnable(GL_POLYGON_OFFSET_FILL);
        glPolygonOffset(-1.0f, -1.0f);
    }
    glDisable(GL_LIGHTING);
    glEnable(GL_TEXTURE_2D);
    glBindTexture(GL_TEXTURE_2D, texture);
    glLoadIdentity();
    glColor3f(1, 1, 1);
    // A normal of its own turned from the styles' head-light: toon shades the poster in its
    // shadow band, so the styled poster differs from the program's (what the rule tests see).
    glNormal3f(0.6f, -0.8f, 0.0f);
    glBegin(GL_QUADS);
    glTexCoord2f(0, 0);
    glVertex3f(0.8f, -1.4f, -2.2f);
    glTexCoord2f(1, 0);
    glVertex3f(1.4f, -1.4f, -2.2f);
    glTexCoord2f(1, 1);
    glVertex3f(1.4f, -0.8f, -2.2f);
    glTexCoord2f(0, 1);
    glVertex3f(0.8f, -0.8f, -2.2f);
    glEnd();
    glDisable(GL_TEXTURE_2D);
    glDisable(GL_POLYGON_OFFSET_FILL);
}

} // namespace

int main(int argc, char** argv)
{
    int frames = 4;
    int size = 128;
    bool textured = false;
    bool decal = false;
    // Key combinations going up (false) or down (true) at the start of a frame.
    std::map<int, std::vector<std::pair<std::string, bool>>> keys;
    std::map<int, std::vector<std::string>> taps;
    std::map<int, std::pair<int, int>> pointer;
    std::map<int, bool> buttons;
    for (int i = 1; i < argc; i += 2) {
        const std::string option = argv[i];
        if (option == "--textured" || option == "--decal") {
            textured = true;
            decal = decal || option == "--decal";
            --i;
        } else if (i + 1 >= argc) {
            std::fprintf(stderr, "probe_hotkeys: %s needs a value\n", argv[i]);
            return 2;
        } else if (option == "--frames") {
            frames = std::atoi(argv[i + 1]);
        } else if (option == "--size") {
            size = std::atoi(argv[i + 1]);
        } else if (option == "--press" && i + 2 < argc) {
            const int frame = std::atoi(argv[i + 1]);
            keys[frame].emplace_back(argv[i + 2], true);
            keys[frame + 1].emplace_back(argv[i + 2], false);
            ++i;
        } else if (option == "--tap" && i + 2 < argc) {
            taps[std::atoi(argv[i + 1])].push_back(argv[i + 2]);
            ++i;
        } else if (option == "--hold" && i + 3 < argc) {
            keys[std::atoi(argv[i + 1])].emplace_back(argv[i + 3], true);
            keys[std::atoi(argv[i + 2])].emplace_back(argv[i + 3], false);
            i += 2;
        } else if (option == "--pointer" && i + 3 < argc) {
            pointer[std::atoi(argv[i + 1])] = {std::atoi(argv[i + 2]), std::atoi(argv[i + 3])};
            i += 2;
        } else if (option == "--button" && i + 2 < argc) {
            buttons[std::atoi(argv[i + 1])] = std::string(argv[i + 2]) == "down";
            ++i;
        } else {
            std::fprintf(stderr, "probe_hotkeys: unknown option %s\n", argv[i]);
            return 2;
        }
    }
    Display* dpy = XOpenDisplay(nullptr);
    int event = 0, error = 0, major = 0, minor = 0;
    if (!dpy || !XTestQueryExtension(dpy, &event, &error, &major, &minor)) {
        std::fprintf(stderr, "probe_hotkeys: no display with XTEST\n");
        return 1;
    }
    int attributes[] = {GLX_RGBA, GLX_DEPTH_SIZE, 24, GLX_DOUBLEBUFFER, None};
    XVisualInfo* visual = glXChooseVisual(dpy, DefaultScreen(dpy), attributes);
    if (!visual) {
        std::fprintf(stderr, "probe_hotkeys: no GLX visual\n");
        return 1;
    }
    XSetWindowAttributes wa{};
    const Window root = RootWindow(dpy, visual->screen);
    wa.colormap = XCreateColormap(dpy, root, visual->visual, AllocNone);
    const Window window = XCreateWindow(dpy, root, 0, 0, size, size, 0, visual->depth,
                                        InputOutput, visual->visual, CWColormap, &wa);
    XMapWindow(dpy, window);
    GLXContext context = glXCreateContext(dpy, visual, nullptr, True);
    glXMakeCurrent(dpy, window, context);
    glViewport(0, 0, size, size);
    XSync(dpy, False);
    const GLuint poster = textured ? makePosterTexture() : 0;
    std::map<std::string, int> held; // combinations down, and how many times
    for (int frame = 1; frame <= frames; ++frame) {
        if (auto k = keys.find(frame); k != keys.end()) {
            // Up first: a combination pressed in two frames in a row goes up between them.
            for (bool down : {false, true}) {
                for (const auto& [combination, d] : k->second) {
                    if (d != down) continue;
                    setKeys(dpy, keycodes(dpy, combination), down);
                    held[combination] += down ? 1 : -1;
                }
            }
        }
        if (auto t = taps.find(frame); t != taps.end()) {
            for (const std::string& combination : t->second) {
                setKeys(dpy, keycodes(dpy, combination), true);
                setKeys(dpy, keycodes(dpy, combination), false);
            }
        }
        if (auto p = pointer.find(frame); p != pointer.end()) {
            // Window pixels to the screen's: there is no window manager to move it, but ask.
            int x = 0, y = 0;
            Window child = 0;
            XTranslateCoordinates(dpy, window, root, p->second.first, p->second.second, &x, &y,
                                  &child);
            XTestFakeMotionEvent(dpy, visual->screen, x, y, CurrentTime);
            XSync(dpy, False);
        }
        if (auto b = buttons.find(frame); b != buttons.end()) {
            XTestFakeButtonEvent(dpy, 1, b->second ? True : False, CurrentTime);
            XSync(dpy, False);
        }
        nprgl::probes::drawCube(frame);
        if (textured) drawPoster(poster, decal);
        glXSwapBuffers(dpy, window);
    }
    for (const auto& [combination, n] : held) {
        if (n > 0) setKeys(dpy, keycodes(dpy, combination), false);
    }
    glXMakeCurrent(dpy, None, nullptr);
    glXDestroyContext(dpy, context);
    XDestroyWindow(dpy, window);
    XFree(visual);
    XCloseDisplay(dpy);
    std::printf("ok\n");
    return 0;
}
