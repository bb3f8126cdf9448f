#include "styles/textures/GlTexture.h"

#include "common/PngImage.h"
#include "styles/ObjectNames.h"

#include <cmath>

namespace nprgl::styles {

void GlTexture::upload(const GlFunctions& gl, const TextureImage& image, bool mipmaps)
{
    if (!mTexture) ObjectNames::reserve(gl, ObjectNames::Kind::Texture, 1, &mTexture);
    gl.BindTexture(GL_TEXTURE_2D, mTexture);
    resetUnpack(gl);
    const bool grey = image.channels == 1;
    gl.TexImage2D(GL_TEXTURE_2D, 0, grey ? GL_R8 : GL_RGBA8, image.width, image.height, 0,
                  grey ? GL_RED : GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
    if (mipmaps) gl.GenerateMipmap(GL_TEXTURE_2D);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                     mipmaps ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
}

void GlTexture::destroy(const GlFunctions& gl)
{
    if (mTexture) gl.DeleteTextures(1, &mTexture);
    mTexture = 0;
}

bool GlTexture::loadPng(const std::string& path, bool grey, TextureImage& out,
                        std::string& error)
{
    PngImage png;
    if (!PngImage::read(path, png, error)) return false;
    if (png.width <= 0 || png.height <= 0) {
        error = "empty image";
        return false;
    }
    out.width = png.width;
    out.height = png.height;
    out.channels = grey ? 1 : 4;
    if (!grey) {
        out.pixels = png.rgba;
        return true;
    }
    out.pixels.resize(size_t(png.width) * png.height);
    for (size_t i = 0; i < out.pixels.size(); ++i) {
        const uint8_t* p = &png.rgba[i * 4];
        // Transparent texels count as paper.
        const float lum = (0.299f * p[0] + 0.587f * p[1] + 0.114f * p[2]) / 255.0f;
        const float a = p[3] / 255.0f;
        out.pixels[i] = uint8_t(std::lround(255.0f * (lum * a + (1.0f - a))));
    }
    return true;
}

void GlTexture::resetUnpack(const GlFunctions& gl)
{
    gl.BindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    gl.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
    gl.PixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    gl.PixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    gl.PixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
}

void GlTexture::allocateNearest(const GlFunctions& gl, GLuint tex, GLint internalFormat,
                                GLenum format, GLenum type, int width, int height)
{
    gl.BindTexture(GL_TEXTURE_2D, tex);
    gl.TexImage2D(GL_TEXTURE_2D, 0, internalFormat, width, height, 0, format, type, nullptr);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

} // namespace nprgl::styles
