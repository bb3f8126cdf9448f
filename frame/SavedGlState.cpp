#include "frame/SavedGlState.h"

#include "shim/RealGl.h"

namespace nprgl {

bool SavedGlState::resolve()
{
    mBindFramebuffer =
        reinterpret_cast<PFNGLBINDFRAMEBUFFERPROC>(realProcAddress("glBindFramebuffer"));
    mBindVertexArray =
        reinterpret_cast<PFNGLBINDVERTEXARRAYPROC>(realProcAddress("glBindVertexArray"));
    mBindRenderbuffer =
        reinterpret_cast<PFNGLBINDRENDERBUFFERPROC>(realProcAddress("glBindRenderbuffer"));
    return mBindFramebuffer && mBindVertexArray && mBindRenderbuffer;
}

bool SavedGlState::save(bool pixelDefaults)
{
    const GlDispatch& gl = gRealGl;
    GLint depth = 0, max = 0, clientDepth = 0, clientMax = 0;
    gl.glGetIntegerv(GL_ATTRIB_STACK_DEPTH, &depth);
    gl.glGetIntegerv(GL_MAX_ATTRIB_STACK_DEPTH, &max);
    gl.glGetIntegerv(GL_CLIENT_ATTRIB_STACK_DEPTH, &clientDepth);
    gl.glGetIntegerv(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, &clientMax);
    if (depth >= max || clientDepth >= clientMax) return false;
    gl.glPushAttrib(GL_ALL_ATTRIB_BITS);
    gl.glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
    gl.glGetIntegerv(GL_CURRENT_PROGRAM, &mProgram);
    gl.glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &mArrayBuffer);
    gl.glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &mVertexArray);
    gl.glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &mDrawFramebuffer);
    gl.glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &mReadFramebuffer);
    gl.glGetIntegerv(GL_RENDERBUFFER_BINDING, &mRenderbuffer);
    gl.glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &mPackBuffer);
    gl.glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &mUnpackBuffer);
    gl.glGetIntegerv(GL_ACTIVE_TEXTURE, &mActiveTexture);
    for (int i = 0; i < 4; ++i) {
        gl.glActiveTexture(GL_TEXTURE0 + i);
        gl.glGetIntegerv(GL_TEXTURE_BINDING_2D, &mTextures[i]);
    }
    gl.glActiveTexture(GL_TEXTURE0);
    if (!pixelDefaults) {
        gl.glActiveTexture(GLenum(mActiveTexture)); // all as the program left it
        return true;
    }
    if (mPackBuffer) gl.glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
    if (mUnpackBuffer) gl.glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
    // What nprgl draws uploads and reads pixels with the default pixel store.
    gl.glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    gl.glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
    gl.glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
    gl.glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
    gl.glPixelStorei(GL_PACK_ALIGNMENT, 4);
    gl.glPixelStorei(GL_PACK_ROW_LENGTH, 0);
    gl.glPixelStorei(GL_PACK_SKIP_ROWS, 0);
    gl.glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
    return true;
}

void SavedGlState::restore()
{
    const GlDispatch& gl = gRealGl;
    for (int i = 3; i >= 0; --i) {
        gl.glActiveTexture(GL_TEXTURE0 + i);
        gl.glBindTexture(GL_TEXTURE_2D, mTextures[i]);
    }
    gl.glActiveTexture(mActiveTexture);
    mBindVertexArray(mVertexArray);
    gl.glBindBuffer(GL_ARRAY_BUFFER, mArrayBuffer);
    gl.glBindBuffer(GL_PIXEL_PACK_BUFFER, mPackBuffer);
    gl.glBindBuffer(GL_PIXEL_UNPACK_BUFFER, mUnpackBuffer);
    mBindFramebuffer(GL_DRAW_FRAMEBUFFER, mDrawFramebuffer);
    mBindFramebuffer(GL_READ_FRAMEBUFFER, mReadFramebuffer);
    mBindRenderbuffer(GL_RENDERBUFFER, mRenderbuffer);
    gl.glUseProgram(mProgram);
    gl.glPopClientAttrib();
    gl.glPopAttrib();
}

} // namespace nprgl
