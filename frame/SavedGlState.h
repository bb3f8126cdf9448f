#pragma once

// SavedGlState: all of the program's GL state, saved before nprgl draws and put back after.

#include "shim/Api.h"

namespace nprgl {

// The attribute stacks (GL_ALL_ATTRIB_BITS, GL_CLIENT_ALL_ATTRIB_BITS) plus what they do not
// hold: the program object, buffer, vertex array and framebuffer bindings, the active unit and
// the 2D textures of units 0-3. Pixel store is reset to the defaults while saved. Calls the
// driver directly (gRealGl), so nothing of it is recorded or followed.
class SavedGlState {
public:
    // Looks up the entry points GL 1.x lacks; false when the driver has no framebuffer
    // objects or vertex arrays (then nothing can be saved).
    bool resolve();
    // False (and nothing changed) when an attribute stack is full. pixelDefaults: the pixel
    // store reset and the pixel buffers unbound for nprgl's uploads and reads; without, they
    // stay the program's (what a replay of its calls needs).
    bool save(bool pixelDefaults = true);
    void restore();

private:
    GLint mProgram = 0, mArrayBuffer = 0, mVertexArray = 0, mDrawFramebuffer = 0,
          mReadFramebuffer = 0, mActiveTexture = 0, mRenderbuffer = 0, mPackBuffer = 0,
          mUnpackBuffer = 0;
    GLint mTextures[4] = {};
    PFNGLBINDFRAMEBUFFERPROC mBindFramebuffer = nullptr;
    PFNGLBINDVERTEXARRAYPROC mBindVertexArray = nullptr;
    PFNGLBINDRENDERBUFFERPROC mBindRenderbuffer = nullptr;
};

} // namespace nprgl
