#pragma once

namespace nprgl {

// libc's dlopen, bypassing our hook: nprgl's own loads must never be redirected.
void* realDlopen(const char* file, int mode);

} // namespace nprgl
