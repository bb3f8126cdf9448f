#pragma once

// OwnGlCalls: nprgl's GL calls in the program's context leave the program's GL errors alone.

#include "shim/Api.h"

namespace nprgl {

// Around GL calls nprgl makes in the program's current context that may raise a GL error
// (the styles' set-up and drawing, a screenshot's read-back, a frame drawn again): the
// program's pending error is taken from the driver first and kept for the program's next
// glGetError (Context::keepProgramError); at the end whatever nprgl's calls raised is
// drained, so the program sees its own errors and none of nprgl's. Calls that cannot fail
// (queries valid for the context's API, version and profile) need none of this: they leave
// the error flag as it is.
class OwnGlCalls {
public:
    OwnGlCalls();
    ~OwnGlCalls() { finish(); }
    OwnGlCalls(const OwnGlCalls&) = delete;
    OwnGlCalls& operator=(const OwnGlCalls&) = delete;

    // Drains what nprgl's calls raised (once); returns the first of it, GL_NO_ERROR if none.
    GLenum finish();
    // Empties the driver's error flags; returns the first error, GL_NO_ERROR if none.
    static GLenum drain();

private:
    bool mFinished = false;
};

} // namespace nprgl
