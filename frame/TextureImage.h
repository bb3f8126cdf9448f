// What an uploaded texture image says about itself: opacity, mean colour, fineness of its cut.
#pragma once

#include "shim/Api.h"

#include <glm/glm.hpp>

#include <cstddef>

namespace nprgl {

// TextureImage::cutFeature of an image an alpha test at one half keeps whole: one texture
// coordinate unit, never fine on screen.
inline constexpr float kKeptWhole = 1.0f;

// Where a texture's alpha comes from. GL keeps the channels of the texture's internal format,
// whatever the pixels it was given: an RGB or luminance texture is opaque even from RGBA
// bytes; GL_INTENSITY takes its alpha from the pixels' first channel (texfont's labels: glyph
// bytes given as GL_LUMINANCE); the others take the pixels' alpha, 1 where they have none.
enum class TextureAlpha { One, FromAlpha, FromIntensity };
TextureAlpha textureAlpha(GLint internalFormat);

// A view of the pixels of one glTexImage2D or glTexSubImage2D as recorded: width x height
// texels of format and type, `bytes` long with each row's unpack padding, for a texture whose
// alpha comes from `alpha`. Each question is one pass over (a sample of) the bytes, asked
// once at upload, never per draw.
class TextureImage {
public:
    TextureImage(GLsizei width, GLsizei height, GLenum format, GLenum type, const void* pixels,
                 size_t bytes, TextureAlpha alpha = TextureAlpha::FromAlpha);

    // Alpha 1 everywhere: a texture without alpha, pixels without alpha that give none, or
    // 8-bit bytes whose alpha (or intensity) is all 255.
    bool opaque() const;
    // The mean colour of an 8-bit image (a sample of at most 64 x 64 texels); false: unknown.
    bool mean(glm::vec3& mean) const;
    // The median length, in texture coordinate units of a level `level` texels wide and high,
    // of the runs of texels an alpha test at one half keeps and of the clear runs they
    // enclose, whichever is shorter, along at most 64 rows and 64 columns (0: not known, or
    // the test keeps nothing; kKeptWhole: it keeps every texel): how fine its cut-out is.
    float cutFeature(glm::ivec2 level) const;

private:
    // Bytes per texel of an 8-bit format and whether its last byte is alpha; 0: not 8-bit.
    int channels(bool& hasAlpha) const;
    // The byte of an 8-bit texel the texture's alpha is read from; -1: none (alpha 1, or
    // not known).
    int alphaByte(int channels, bool hasAlpha) const;
    // Bytes from one row to the next, 0 when the bytes cannot hold the image.
    size_t rowBytes(int channels) const;

    GLsizei mWidth, mHeight;
    GLenum mFormat, mType;
    const unsigned char* mPixels;
    size_t mBytes;
    TextureAlpha mAlpha;
};

} // namespace nprgl
