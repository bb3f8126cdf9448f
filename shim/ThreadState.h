#pragma once

#include "shim/Api.h"

namespace nprgl {

class Context;

// What the thunks read on every call. initial-exec TLS: one %fs-relative load, no
// __tls_get_addr call, which matters at a million glVertex calls per frame (Mesa's glapi
// does the same). The library is preloaded, so static TLS is available.
struct ThreadState {
    const GlDispatch* dispatch; // never null: the real table when no context is current
    Context* context;           // the current nprgl Context, or null
};

extern constinit thread_local ThreadState tThread __attribute__((tls_model("initial-exec")));

// Makes calls that our own code (or the driver) makes through the exported symbols go
// straight to the driver, re-entering nothing.
class ReentryGuard {
public:
    ReentryGuard();
    ~ReentryGuard();
    ReentryGuard(const ReentryGuard&) = delete;
    ReentryGuard& operator=(const ReentryGuard&) = delete;

private:
    const GlDispatch* mSaved;
};

} // namespace nprgl
