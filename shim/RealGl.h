#pragma once

#include "shim/Api.h"

namespace nprgl {

// The driver's entry points. Slots start as lazy resolvers, so nothing is looked up until the
// program makes its first call: a program that never uses GL never resolves anything.
extern GlDispatch gRealGl;
extern WsDispatch gRealWs;

// Looks up every slot (idempotent and thread-safe). Order per name: the library named by
// NPRGL_REAL_LIBGL, dlsym(RTLD_NEXT), the GL libraries the program dlopen'ed, the driver's
// own GetProcAddress, then dlopen("libGL.so.1").
void resolveReal();
// Called by the dlopen hook: a GL library the program opened privately joins the search and
// slots still missing are looked up again.
void addRealLibrary(void* handle);
// Any real function by name, including those beyond GL 2.1 that the renderer needs.
void* realProcAddress(const char* name);

// True when slot i of kGlEntries / kWsEntries has a real function behind it.
bool realGlFound(size_t index);
bool realWsFound(size_t index);

// True when p lies inside nprgl itself (or another copy of it).
bool isOwnAddress(const void* p);

} // namespace nprgl
