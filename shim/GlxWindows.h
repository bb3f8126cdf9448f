#pragma once

// GlxWindows: the X window behind each GLXWindow the program made (glXCreateWindow).

#include <X11/X.h>

#include <mutex>
#include <unordered_map>

namespace nprgl {

// A GLX 1.3 drawable is not an X window: asking X about it (XQueryPointer) would raise
// BadWindow in the program. A GLX 1.2 program draws to the X window itself.
class GlxWindows {
public:
    static GlxWindows& instance();

    void add(XID glxWindow, Window window);
    void remove(XID glxWindow);
    // The X window of a drawable: its window when glXCreateWindow made it, else the drawable.
    Window windowOf(XID drawable) const;

private:
    mutable std::mutex mMutex;
    std::unordered_map<XID, Window> mWindows;
};

} // namespace nprgl
