#pragma once

#include "shim/Context.h"

#include <string>

namespace nprgl {

// Reads the default framebuffer's back (or only) buffer into a PNG, leaving every piece of
// state the program can see as it was: pixel-pack parameters, pack buffer, read framebuffer,
// read buffer, and no GL error added.
class FrameGrabber {
public:
    static bool writeFrame(const ContextCaps& caps, int width, int height,
                           const std::string& path);
};

} // namespace nprgl
