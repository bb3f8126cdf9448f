// Programs that load GL themselves (SDL, ioquake3, glretrace, LWJGL) dlopen libGL.so.1 and
// dlsym their entry points from that handle, where a preloaded library is never looked at.
// We let the real library load (its handle joins the real-function search) and hand the
// program a handle to nprgl instead, whose exports forward to it.

#include "shim/DlopenHook.h"

#include "common/Log.h"
#include "shim/RealGl.h"

#include <cstring>
#include <dlfcn.h>
#include <regex>

namespace nprgl {

namespace {

const char* baseName(const char* path)
{
    const char* slash = std::strrchr(path, '/');
    return slash ? slash + 1 : path;
}

// libGL.so, libGL.so.1, libGLX.so.0, libOpenGL.so.0.0.0, libOSMesa.so.8 ...
bool isGlLibrary(const char* path)
{
    static const std::regex kPattern("lib(GL|GLX|OpenGL|OSMesa)\\.so(\\.[0-9]+)*");
    return std::regex_match(baseName(path), kPattern);
}

// GL libraries load each other (glvnd's libGL loads libGLX); those must get the real thing.
bool callerIsGlStack(const void* caller)
{
    Dl_info info{};
    if (!dladdr(caller, &info) || !info.dli_fname) return false;
    const char* name = baseName(info.dli_fname);
    static const char* const kPrefixes[] = {"libGL",   "libEGL",    "libOpenGL", "libOSMesa",
                                            "libglapi", "libgallium", "libnprgl", "libGLES"};
    for (const char* prefix : kPrefixes) {
        if (std::strncmp(name, prefix, std::strlen(prefix)) == 0) return true;
    }
    return std::strstr(name, "_dri.so") != nullptr;
}

void* selfHandle()
{
    Dl_info info{};
    dladdr(reinterpret_cast<void*>(&realDlopen), &info);
    return info.dli_fname ? realDlopen(info.dli_fname, RTLD_NOW | RTLD_NOLOAD) : nullptr;
}

} // namespace

void* realDlopen(const char* file, int mode)
{
    using DlopenFn = void* (*)(const char*, int);
    static DlopenFn fn = reinterpret_cast<DlopenFn>(dlsym(RTLD_NEXT, "dlopen"));
    return fn(file, mode);
}

} // namespace nprgl

extern "C" __attribute__((visibility("default"))) void* dlopen(const char* file, int mode)
{
    using namespace nprgl;
    const void* caller = __builtin_return_address(0);
    void* handle = realDlopen(file, mode);
    if (!handle || !file || !isGlLibrary(file) || callerIsGlStack(caller)) return handle;
    addRealLibrary(handle);
    void* self = selfHandle();
    if (!self) return handle;
    NPRGL_DEBUG("dlopen(\"%s\") answered with nprgl", file);
    return self;
}
