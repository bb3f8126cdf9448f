#include "shim/RealGl.h"

#include "common/Log.h"
#include "shim/DlopenHook.h"

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <mutex>
#include <vector>

#pragma GCC diagnostic ignored "-Wunused-parameter"

namespace nprgl {

namespace {

template <typename T>
T zeroValue()
{
    return T{};
}
template <>
void zeroValue<void>()
{
}

void reportMissing(const char* name);

// Called when the program reaches a slot before anything was resolved.
namespace lazy {
#define NPRGL_GL(ret, name, params, args)                                                      \
    ret name params                                                                            \
    {                                                                                          \
        resolveReal();                                                                         \
        return gRealGl.name args;                                                              \
    }
#define NPRGL_WS(api, hooked, ret, name, params, args)                                         \
    ret name params                                                                            \
    {                                                                                          \
        resolveReal();                                                                         \
        return gRealWs.name args;                                                              \
    }
#include "nprgl_api.inc"
} // namespace lazy

// Called when no real function exists: say so once, answer zero, keep the program alive.
namespace missing {
#define NPRGL_GL(ret, name, params, args)                                                      \
    ret name params                                                                            \
    {                                                                                          \
        reportMissing(#name);                                                                  \
        return zeroValue<ret>();                                                               \
    }
#define NPRGL_WS(api, hooked, ret, name, params, args) NPRGL_GL(ret, name, params, args)
#include "nprgl_api.inc"
} // namespace missing

std::mutex gResolveMutex;
std::atomic<bool> gResolved{false};
std::vector<void*> gExtraLibraries; // dlopen'ed privately by the program (RTLD_LOCAL)
void* gOverrideLibrary = nullptr;
void* gDefaultLibrary = nullptr;
bool gGlFound[4096];
bool gWsFound[128];
std::atomic<bool> gMissingReported{false};

void reportMissing(const char* name)
{
    if (!gMissingReported.exchange(true)) {
        NPRGL_ERROR("%s has no real implementation: no OpenGL library was found (tried "
                    "NPRGL_REAL_LIBGL, the program's own libraries and libGL.so.1); GL calls "
                    "do nothing",
                    name);
    }
}

using GetProc = void* (*)(const char*);

void* ownBase()
{
    static void* base = [] {
        Dl_info info{};
        dladdr(reinterpret_cast<void*>(&resolveReal), &info);
        return info.dli_fbase;
    }();
    return base;
}

// A "real" function inside nprgl would forward to itself forever: refuse it loudly and go on
// searching, rather than abort the host program.
void* lookupIn(void* handle, const char* name)
{
    void* p = handle ? dlsym(handle, name) : nullptr;
    if (p && isOwnAddress(p)) {
        static std::atomic<bool> reported{false};
        if (!reported.exchange(true)) {
            NPRGL_ERROR("the real %s resolves to nprgl itself (is libnprgl loaded twice?); "
                        "skipping it",
                        name);
        }
        return nullptr;
    }
    return p;
}

// The driver's GetProcAddress answers for any name (glvnd makes stubs), so it is asked only
// after every library has been searched, and only for names we know.
void* lookupByGetProc(const char* name)
{
    static const char* const kGetProcs[] = {"glXGetProcAddressARB", "OSMesaGetProcAddress",
                                            "eglGetProcAddress"};
    for (const char* gpaName : kGetProcs) {
        void* gpa = lookupIn(RTLD_NEXT, gpaName);
        for (size_t i = 0; !gpa && i < gExtraLibraries.size(); ++i) {
            gpa = lookupIn(gExtraLibraries[i], gpaName);
        }
        if (!gpa) continue;
        void* p = reinterpret_cast<GetProc>(gpa)(name);
        if (p && !isOwnAddress(p)) return p;
    }
    return nullptr;
}

void openDefaultLibraries()
{
    if (const char* path = std::getenv("NPRGL_REAL_LIBGL"); path && *path) {
        static bool tried = false;
        if (!tried) {
            tried = true;
            gOverrideLibrary = realDlopen(path, RTLD_NOW | RTLD_LOCAL);
            if (!gOverrideLibrary) {
                NPRGL_ERROR("cannot load NPRGL_REAL_LIBGL=%s: %s", path, dlerror());
            }
        }
    }
}

// Resolution of one name, under gResolveMutex.
void* findReal(const char* name, bool glCommand)
{
    if (void* p = lookupIn(gOverrideLibrary, name)) return p;
    if (void* p = lookupIn(RTLD_NEXT, name)) return p;
    for (void* handle : gExtraLibraries) {
        if (void* p = lookupIn(handle, name)) return p;
    }
    if (glCommand) {
        if (void* p = lookupByGetProc(name)) return p;
    }
    // Last resort, as the design says; not when the user named another library.
    if (!gDefaultLibrary && !std::getenv("NPRGL_REAL_LIBGL")) {
        gDefaultLibrary = realDlopen("libGL.so.1", RTLD_NOW | RTLD_LOCAL);
    }
    return lookupIn(gDefaultLibrary, name);
}

template <typename Fn>
void assign(Fn& slot, bool& found, const char* name, bool glCommand, Fn missingFn)
{
    if (found) return;
    void* p = findReal(name, glCommand);
    found = p != nullptr;
    slot = found ? reinterpret_cast<Fn>(p) : missingFn;
}

// Fills every slot not found yet. Caller holds gResolveMutex.
void resolveLocked()
{
    openDefaultLibraries();
    size_t gl = 0, ws = 0;
#define NPRGL_GL(ret, name, params, args)                                                      \
    assign(gRealGl.name, gGlFound[gl++], #name, true, &missing::name);
#define NPRGL_WS(api, hooked, ret, name, params, args)                                         \
    assign(gRealWs.name, gWsFound[ws++], #name, false, &missing::name);
#include "nprgl_api.inc"
    gResolved.store(true, std::memory_order_release);
}

} // namespace

GlDispatch gRealGl = {
#define NPRGL_GL(ret, name, params, args) &lazy::name,
#include "nprgl_api.inc"
};

WsDispatch gRealWs = {
#define NPRGL_WS(api, hooked, ret, name, params, args) &lazy::name,
#include "nprgl_api.inc"
};

const ApiEntry kGlEntries[] = {
#define NPRGL_GL(ret, name, params, args) {#name, reinterpret_cast<void*>(&::name)},
#include "nprgl_api.inc"
};
const size_t kGlEntryCount = sizeof kGlEntries / sizeof kGlEntries[0];

const ApiEntry kWsEntries[] = {
#define NPRGL_WS(api, hooked, ret, name, params, args) {#name, reinterpret_cast<void*>(&::name)},
#include "nprgl_api.inc"
};
const size_t kWsEntryCount = sizeof kWsEntries / sizeof kWsEntries[0];

static_assert(sizeof(gGlFound) >= sizeof kGlEntries / sizeof kGlEntries[0]);
static_assert(sizeof(gWsFound) >= sizeof kWsEntries / sizeof kWsEntries[0]);

void resolveReal()
{
    if (gResolved.load(std::memory_order_acquire)) return;
    std::lock_guard lock(gResolveMutex);
    if (!gResolved.load(std::memory_order_relaxed)) resolveLocked();
}

void addRealLibrary(void* handle)
{
    std::lock_guard lock(gResolveMutex);
    for (void* h : gExtraLibraries) {
        if (h == handle) return;
    }
    gExtraLibraries.push_back(handle);
    // Only slots still missing change; the program may already be calling the others.
    if (gResolved.load(std::memory_order_relaxed)) resolveLocked();
}

void* realProcAddress(const char* name)
{
    resolveReal();
    std::lock_guard lock(gResolveMutex);
    return findReal(name, std::strncmp(name, "gl", 2) == 0 && name[2] != 'X');
}

bool realGlFound(size_t index)
{
    resolveReal();
    return index < kGlEntryCount && gGlFound[index];
}

bool realWsFound(size_t index)
{
    resolveReal();
    return index < kWsEntryCount && gWsFound[index];
}

bool isOwnAddress(const void* p)
{
    Dl_info info{};
    if (!dladdr(p, &info)) return false;
    if (info.dli_fbase == ownBase()) return true;
    // Another copy of nprgl (preloaded twice under two paths) would forward to itself.
    const char* base = info.dli_fname ? std::strrchr(info.dli_fname, '/') : nullptr;
    base = base ? base + 1 : info.dli_fname;
    return base && std::strncmp(base, "libnprgl", 8) == 0;
}

} // namespace nprgl
