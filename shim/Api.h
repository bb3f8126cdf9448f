#pragma once

// The GL, GLX, EGL and OSMesa declarations nprgl wraps, and the dispatch tables made from the
// generated command list (nprgl_api.inc in the build tree, from shim/gen_api.py).

#include <EGL/egl.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/glx.h>
#include <GL/osmesa.h>

// X11 headers define these as macros; they clash with ordinary C++ names.
#undef None
#undef Status
#undef Success
#undef Always
#undef Bool
#undef True
#undef False
using Bool = int; // Xlib's Bool, as a type rather than a macro

#include <cstddef>

// Every command of the list, declared from the registry (the system headers leave the
// GL 1.2+ and GLX extension prototypes out unless asked).
extern "C" {
#define NPRGL_GL(ret, name, params, args) ret name params;
#define NPRGL_GL_ALIAS(ret, name, params, args, core) ret name params;
#define NPRGL_WS(api, hooked, ret, name, params, args) ret name params;
#include "nprgl_api.inc"
}

namespace nprgl {

// One pointer per GL 1.0-2.1 command. The real table, per-context tables and (later) the
// recording table all have this layout, so switching behaviour is one pointer per thread.
struct GlDispatch {
#define NPRGL_GL(ret, name, params, args) ret(*name) params;
#include "nprgl_api.inc"
};

// The window-system entry points, resolved from the real libraries.
struct WsDispatch {
#define NPRGL_WS(api, hooked, ret, name, params, args) ret(*name) params;
#include "nprgl_api.inc"
};

// Our own implementations of the hooked window-system calls.
namespace hooks {
#define NPRGL_WS_HOOK_1(ret, name, params) ret name params;
#define NPRGL_WS_HOOK_0(ret, name, params)
#define NPRGL_WS(api, hooked, ret, name, params, args) NPRGL_WS_HOOK_##hooked(ret, name, params)
#include "nprgl_api.inc"
#undef NPRGL_WS_HOOK_0
#undef NPRGL_WS_HOOK_1
} // namespace hooks

// Counts and names, in list order.
struct ApiEntry {
    const char* name;
    void* thunk; // our exported entry point
};
extern const ApiEntry kGlEntries[];
extern const size_t kGlEntryCount;
extern const ApiEntry kWsEntries[];
extern const size_t kWsEntryCount;

// ARB/EXT names of commands of the list: their thunks take the command's own path.
struct ApiAlias {
    const char* name;
    void* thunk;
    const char* core;
};
extern const ApiAlias kGlAliases[];
extern const size_t kGlAliasCount;

} // namespace nprgl
