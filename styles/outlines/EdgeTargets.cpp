#include "styles/outlines/EdgeTargets.h"

#include "styles/ObjectNames.h"
#include "styles/textures/GlTexture.h"

#include <algorithm>

namespace nprgl::styles {

bool EdgeTargets::ensure(const GlFunctions& gl, int width, int height)
{
    // Grown, never shrunk: a program that alternates viewports (a game's view, then its
    // status bar's 3D icons) would otherwise reallocate at every flush, and the driver frees
    // the old storage only once the queued drawing that used it is done.
    if (mFbo[0] && width <= mWidth && height <= mHeight) return mComplete;
    width = std::max(width, mWidth);
    height = std::max(height, mHeight);
    destroy(gl);
    mWidth = width;
    mHeight = height;
    ObjectNames::reserve(gl, ObjectNames::Kind::Texture, 3, mTex);
    ObjectNames::reserve(gl, ObjectNames::Kind::Framebuffer, 3, mFbo);
    ObjectNames::reserve(gl, ObjectNames::Kind::Renderbuffer, 1, &mDepth);
    GlTexture::allocateNearest(gl, mTex[0], GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, width,
                               height);
    GlTexture::allocateNearest(gl, mTex[1], GL_RGBA32F, GL_RGBA, GL_FLOAT, width, height);
    GlTexture::allocateNearest(gl, mTex[2], GL_RGBA32F, GL_RGBA, GL_FLOAT, width, height);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.BindRenderbuffer(GL_RENDERBUFFER, mDepth);
    gl.RenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width, height);
    gl.BindRenderbuffer(GL_RENDERBUFFER, 0);

    mComplete = true;
    const GLenum one[] = {GL_COLOR_ATTACHMENT0};
    for (int i = 0; i < 3; ++i) {
        gl.BindFramebuffer(GL_FRAMEBUFFER, mFbo[i]);
        gl.FramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, mTex[i], 0);
        if (i == 0) {
            gl.FramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER,
                                       mDepth);
        }
        gl.DrawBuffers(1, one);
        mComplete =
            mComplete && gl.CheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    }
    return mComplete;
}

void EdgeTargets::destroy(const GlFunctions& gl)
{
    if (mFbo[0]) gl.DeleteFramebuffers(3, mFbo);
    if (mTex[0]) gl.DeleteTextures(3, mTex);
    if (mDepth) gl.DeleteRenderbuffers(1, &mDepth);
    for (GLuint& f : mFbo) f = 0;
    for (GLuint& t : mTex) t = 0;
    mDepth = 0;
    mWidth = mHeight = 0;
    mComplete = false;
}

} // namespace nprgl::styles
