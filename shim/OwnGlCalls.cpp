#include "shim/OwnGlCalls.h"

#include "common/Log.h"
#include "shim/Context.h"
#include "shim/RealGl.h"
#include "shim/ThreadState.h"

namespace nprgl {

namespace {

// A driver keeps one error flag (Mesa) or a few (the spec allows one per kind of error);
// bounded all the same, so a broken driver cannot hang the program here.
constexpr int kMaxFlags = 16;

} // namespace

OwnGlCalls::OwnGlCalls()
{
    const GLenum programError = gRealGl.glGetError();
    if (programError == GL_NO_ERROR) return;
    if (Context* ctx = tThread.context) {
        ctx->keepProgramError(programError);
    } else {
        NPRGL_DEBUG("GL error 0x%x pending without a current context of nprgl's", programError);
    }
}

GLenum OwnGlCalls::finish()
{
    if (mFinished) return GL_NO_ERROR;
    mFinished = true;
    return drain();
}

GLenum OwnGlCalls::drain()
{
    GLenum first = GL_NO_ERROR;
    for (int i = 0; i < kMaxFlags; ++i) {
        const GLenum e = gRealGl.glGetError();
        if (e == GL_NO_ERROR) break;
        if (first == GL_NO_ERROR) first = e;
    }
    return first;
}

} // namespace nprgl
