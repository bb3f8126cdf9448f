// FrameGrabber: the window's picture read back without the program seeing it.
#pragma once

#include "shim/Context.h"

#include <cstdint>
#include <string>

namespace nprgl {

// Reads the default framebuffer's back (or only) buffer into a PNG, leaving every piece of
// state the program can see as it was: pixel-pack parameters, pack buffer, read framebuffer,
// read buffer, and no GL error added.
class FrameGrabber {
public:
    static bool writeFrame(const ContextCaps& caps, int width, int height,
                           const std::string& path);
    // Why the frame cannot be read now (no GL version, no size, inside glNewList), else null.
    static const char* cannotRead(const ContextCaps& caps, int width, int height);
    // Reads width x height RGBA pixels, bottom row first, into rgba; GL_NO_ERROR or the error
    // the driver raised for the read (taken from it: the program never sees it).
    static GLenum readFrame(const ContextCaps& caps, int width, int height, uint8_t* rgba);
};

} // namespace nprgl
