// The exported entry points, one per command of the generated list and one per alias.
//
// A GL thunk is one thread-local load and an indirect tail call: the current context's table
// while nprgl has a context on this thread, the driver's otherwise. Nothing allocates, locks
// or branches per call. Window-system thunks go to our hooks or straight to the driver.

#include "shim/Api.h"
#include "shim/RealGl.h"
#include "shim/ThreadState.h"

#define NPRGL_EXPORT extern "C" __attribute__((visibility("default")))

#define NPRGL_GL(ret, name, params, args)                                                      \
    NPRGL_EXPORT ret name params { return nprgl::tThread.dispatch->name args; }
// An alias (glBindBufferARB) is the command it names (glBindBuffer): same slot, so it is
// recorded, followed and held exactly like it.
#define NPRGL_GL_ALIAS(ret, name, params, args, core)                                          \
    NPRGL_EXPORT ret name params { return nprgl::tThread.dispatch->core args; }
#define NPRGL_WS_THUNK_1(ret, name, params, args)                                              \
    NPRGL_EXPORT ret name params { return nprgl::hooks::name args; }
#define NPRGL_WS_THUNK_0(ret, name, params, args)                                              \
    NPRGL_EXPORT ret name params { return nprgl::gRealWs.name args; }
#define NPRGL_WS(api, hooked, ret, name, params, args)                                         \
    NPRGL_WS_THUNK_##hooked(ret, name, params, args)
#include "nprgl_api.inc"
