#include "shim/OverlayInput.h"

#include "common/Log.h"

#include <X11/Xlib.h>
#include <dlfcn.h>

namespace nprgl {

namespace {

using QueryPointer = Bool (*)(Display*, Window, Window*, Window*, int*, int*, int*, int*,
                              unsigned*);

QueryPointer queryPointer()
{
    static const QueryPointer f = [] {
        auto q = reinterpret_cast<QueryPointer>(dlsym(RTLD_DEFAULT, "XQueryPointer"));
        if (!q)
            NPRGL_WARN("Xlib's XQueryPointer is not in this process: the overlay takes no "
                       "pointer input");
        return q;
    }();
    return f;
}

struct Keyboard {
    int (*queryKeymap)(Display*, char[32]) = nullptr;
    KeyCode (*toKeycode)(Display*, KeySym) = nullptr;
    KeySym (*toKeysym)(Display*, KeyCode, int) = nullptr;
};

const Keyboard& keyboard()
{
    static const Keyboard k = [] {
        Keyboard f;
        f.queryKeymap =
            reinterpret_cast<decltype(f.queryKeymap)>(dlsym(RTLD_DEFAULT, "XQueryKeymap"));
        f.toKeycode =
            reinterpret_cast<decltype(f.toKeycode)>(dlsym(RTLD_DEFAULT, "XKeysymToKeycode"));
        // Deprecated for XKB's, but in every libX11 and enough for the overlay's text fields.
        f.toKeysym =
            reinterpret_cast<decltype(f.toKeysym)>(dlsym(RTLD_DEFAULT, "XKeycodeToKeysym"));
        if (!f.queryKeymap || !f.toKeycode || !f.toKeysym) {
            NPRGL_WARN("Xlib's keyboard functions are not in this process: the overlay takes no "
                       "keys");
        }
        return f;
    }();
    return k;
}

} // namespace

bool OverlayInput::pollKeys(_XDisplay* display, char keymap[32]) const
{
    const Keyboard& k = keyboard();
    if (!k.queryKeymap || !k.toKeycode || !k.toKeysym || !display) return false;
    k.queryKeymap(display, keymap);
    return true;
}

unsigned OverlayInput::keycode(_XDisplay* display, unsigned long sym) const
{
    const Keyboard& k = keyboard();
    return k.toKeycode && display ? k.toKeycode(display, KeySym(sym)) : 0;
}

unsigned long OverlayInput::keysym(_XDisplay* display, unsigned code, bool shifted) const
{
    const Keyboard& k = keyboard();
    return k.toKeysym && display ? k.toKeysym(display, KeyCode(code), shifted ? 1 : 0) : 0;
}

PointerState OverlayInput::poll(_XDisplay* display, Window window, int width, int height) const
{
    PointerState p;
    const QueryPointer query = queryPointer();
    if (!query || !display || !window) return p;
    Window root = 0, child = 0;
    int rootX = 0, rootY = 0, x = 0, y = 0;
    unsigned mask = 0;
    // False: the pointer is on another screen (x, y say nothing then).
    if (!query(display, window, &root, &child, &rootX, &rootY, &x, &y, &mask)) return p;
    p.inside = x >= 0 && y >= 0 && x < width && y < height;
    p.x = float(x);
    p.y = float(y);
    p.buttons[0] = (mask & Button1Mask) != 0;
    p.buttons[1] = (mask & Button3Mask) != 0;
    p.buttons[2] = (mask & Button2Mask) != 0;
    return p;
}

} // namespace nprgl
