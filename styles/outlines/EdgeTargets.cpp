#include "styles/outlines/EdgeTargets.h"

namespace nprgl::styles {

namespace {

void makeTexture(const GlFunctions& gl, GLuint tex, GLint internal, GLenum format, GLenum type,
                 int width, int height)
{
    gl.BindTexture(GL_TEXTURE_2D, tex);
    gl.TexImage2D(GL_TEXTURE_2D, 0, internal, width, height, 0, format, type, nullptr);
    // Read with texelFetch only; nearest keeps the texture complete without mipmaps.
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

} // namespace

bool EdgeTargets::ensure(const GlFunctions& gl, int width, int height)
{
    if (mFbo[0] && width == mWidth && height == mHeight) return mComplete;
    destroy(gl);
    mWidth = width;
    mHeight = height;
    gl.GenTextures(3, mTex);
    gl.GenFramebuffers(3, mFbo);
    gl.GenRenderbuffers(1, &mDepth);
    makeTexture(gl, mTex[0], GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, width, height);
    makeTexture(gl, mTex[1], GL_RGBA32F, GL_RGBA, GL_FLOAT, width, height);
    makeTexture(gl, mTex[2], GL_RGBA32F, GL_RGBA, GL_FLOAT, width, height);
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
