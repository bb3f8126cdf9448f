#pragma once

#include "Image.h"
#include "Options.h"

#include <string>

namespace demo {

// Where frames go: a GLX window or an OSMesa memory buffer.
class Surface {
public:
    virtual ~Surface() = default;

    // Creates the surface and makes its context current.
    virtual bool open(const Options& options, std::string& error) = 0;
    // Returns false once the user has asked to quit.
    virtual bool processEvents() = 0;
    // Called once per frame after drawing, before readPixels and present.
    virtual void finishFrame() = 0;
    // Reads the frame just drawn, top row first.
    virtual void readPixels(Image& image) = 0;
    virtual void present() = 0;
    // Resizes a window (what the program draws keeps its own viewport); nothing offscreen.
    virtual void resize(int /*width*/, int /*height*/) {}
    // Holds keys ('+'-joined X keysym names) down or lets them go (a window; offscreen none).
    virtual void pressKeys(const std::string& /*keys*/, bool /*down*/) {}
};

} // namespace demo
