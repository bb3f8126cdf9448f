#include "shim/GlxWindows.h"

namespace nprgl {

GlxWindows& GlxWindows::instance()
{
    static GlxWindows* windows = new GlxWindows; // lives past exit, as the contexts do
    return *windows;
}

void GlxWindows::add(XID glxWindow, Window window)
{
    std::lock_guard lock(mMutex);
    mWindows[glxWindow] = window;
}

void GlxWindows::remove(XID glxWindow)
{
    std::lock_guard lock(mMutex);
    mWindows.erase(glxWindow);
}

Window GlxWindows::windowOf(XID drawable) const
{
    std::lock_guard lock(mMutex);
    auto it = mWindows.find(drawable);
    return it == mWindows.end() ? drawable : it->second;
}

} // namespace nprgl
