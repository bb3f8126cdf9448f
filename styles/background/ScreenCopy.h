#pragma once

#include "styles/GlFunctions.h"

#include <glm/glm.hpp>

namespace nprgl::styles {

// A copy of the viewport's colour as the bound draw framebuffer holds it, for passes that
// read the picture while they write it. The textures are the viewport's size,
// recreated when it changes, and read with texelFetch (pixel (0, 0) = the viewport's corner).
class ScreenCopy {
public:
    // False when the buffer cannot be copied (multisampled, or no colour buffer drawn to).
    bool capture(const GlFunctions& gl, const glm::ivec4& viewport);
    void destroy(const GlFunctions& gl);

    GLuint colour() const { return mColour; }
    // The bits of the framebuffer's red channel: how finely it can store a colour.
    int colourBits() const { return mColourBits; }

private:
    void ensure(const GlFunctions& gl, int width, int height);

    GLuint mColour = 0;
    int mWidth = 0;
    int mHeight = 0;
    int mColourBits = 8;
};

} // namespace nprgl::styles
