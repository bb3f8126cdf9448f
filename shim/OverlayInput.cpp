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
        if (!q) NPRGL_WARN("Xlib's XQueryPointer is not in this process: the overlay takes no "
                           "pointer input");
        return q;
    }();
    return f;
}

} // namespace

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
