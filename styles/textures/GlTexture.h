#pragma once

#include "styles/GlFunctions.h"
#include "styles/textures/TextureImage.h"

#include <string>

namespace nprgl::styles {

// One repeating GL texture made from a TextureImage (grey images become GL_R8, RGBA ones
// GL_RGBA8), mipmapped unless asked not to. Call upload() from a style's render(), where the
// compositor has saved the program's state: it sets the unpack state and the texture binding
// of the active unit.
class GlTexture {
public:
    // Without mipmaps the texture is bilinear at every size: for screens that are never
    // minified (one texel per pixel or larger), where mipmaps only cost sampling time.
    void upload(const GlFunctions& gl, const TextureImage& image, bool mipmaps = true);
    void destroy(const GlFunctions& gl);
    GLuint id() const { return mTexture; }
    bool valid() const { return mTexture != 0; }

    // The default unpack state and no pixel-unpack buffer: the program may have left any.
    static void resetUnpack(const GlFunctions& gl);
    // Allocates level 0 of texture `tex` (width x height, no data) for texelFetch reads:
    // nearest filtering (complete without mipmaps), clamped to the edge. Leaves it bound.
    static void allocateNearest(const GlFunctions& gl, GLuint tex, GLint internalFormat,
                                GLenum format, GLenum type, int width, int height);

    // Reads a PNG as a texture: grey (its luminance) or RGBA. False with a message on a
    // missing or unreadable file.
    static bool loadPng(const std::string& path, bool grey, TextureImage& out,
                        std::string& error);

private:
    GLuint mTexture = 0;
};

} // namespace nprgl::styles
