#pragma once

#include "styles/GlFunctions.h"
#include "styles/textures/TextureImage.h"

#include <string>

namespace nprgl::styles {

// One repeating, mipmapped GL texture made from a TextureImage (grey images become GL_R8,
// RGBA ones GL_RGBA8). Call upload() from a style's render(), where the compositor has saved
// the program's state: it sets the unpack state and the texture binding of the active unit.
class GlTexture {
public:
    void upload(const GlFunctions& gl, const TextureImage& image);
    void destroy(const GlFunctions& gl);
    GLuint id() const { return mTexture; }
    bool valid() const { return mTexture != 0; }

    // Reads a PNG as a texture: grey (its luminance) or RGBA. False with a message on a
    // missing or unreadable file.
    static bool loadPng(const std::string& path, bool grey, TextureImage& out,
                        std::string& error);

private:
    GLuint mTexture = 0;
};

} // namespace nprgl::styles
