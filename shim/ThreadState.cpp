#include "shim/ThreadState.h"

#include "shim/RealGl.h"

namespace nprgl {

constinit thread_local ThreadState tThread __attribute__((tls_model("initial-exec"))) = {&gRealGl,
                                                                                 nullptr};

ReentryGuard::ReentryGuard() : mSaved(tThread.dispatch) { tThread.dispatch = &gRealGl; }

ReentryGuard::~ReentryGuard() { tThread.dispatch = mSaved; }

} // namespace nprgl
