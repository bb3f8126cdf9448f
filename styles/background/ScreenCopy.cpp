#include "styles/background/ScreenCopy.h"

#include "styles/ObjectNames.h"
#include "styles/textures/GlTexture.h"

#include <algorithm>

namespace nprgl::styles {

void ScreenCopy::ensure(const GlFunctions& gl, int width, int height)
{
    // Grown, never shrunk (see EdgeTargets::ensure).
    if (mColour && width <= mWidth && height <= mHeight) return;
    width = std::max(width, mWidth);
    height = std::max(height, mHeight);
    destroy(gl);
    mWidth = width;
    mHeight = height;
    ObjectNames::reserve(gl, ObjectNames::Kind::Texture, 1, &mColour);
    GlTexture::allocateNearest(gl, mColour, GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, width, height);
}

bool ScreenCopy::capture(const GlFunctions& gl, const glm::ivec4& viewport)
{
    const int width = viewport.z, height = viewport.w;
    if (width <= 0 || height <= 0) return false;
    GLint samples = 0, drawBuffer = GL_NONE, drawFbo = 0, readFbo = 0;
    gl.GetIntegerv(GL_SAMPLE_BUFFERS, &samples);
    gl.GetIntegerv(GL_DRAW_BUFFER, &drawBuffer);
    // A multisampled buffer would need a resolve first; copying it is an error.
    if (samples > 0 || drawBuffer == GL_NONE) return false;
    // ReadBuffer takes one side; the back buffer is the one being drawn.
    if (drawBuffer == GL_FRONT_AND_BACK) drawBuffer = GL_BACK;
    GLint redBits = 0;
    gl.GetIntegerv(GL_RED_BITS, &redBits);
    mColourBits = redBits > 0 ? redBits : 8;

    gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo);
    gl.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFbo);
    // Read from what is being drawn; the read buffer belongs to that framebuffer, so put
    // its own back before leaving.
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(drawFbo));
    GLint readBuffer = GL_NONE;
    gl.GetIntegerv(GL_READ_BUFFER, &readBuffer);
    if (readBuffer != drawBuffer) gl.ReadBuffer(GLenum(drawBuffer));

    ensure(gl, width, height);
    gl.BindTexture(GL_TEXTURE_2D, mColour);
    gl.CopyTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, viewport.x, viewport.y, width, height);
    gl.BindTexture(GL_TEXTURE_2D, 0);

    if (readBuffer != drawBuffer) gl.ReadBuffer(GLenum(readBuffer));
    gl.BindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFbo));
    return true;
}

void ScreenCopy::destroy(const GlFunctions& gl)
{
    if (mColour) gl.DeleteTextures(1, &mColour);
    mColour = 0;
    mWidth = mHeight = 0;
}

} // namespace nprgl::styles
