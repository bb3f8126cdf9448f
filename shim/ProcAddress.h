#pragma once

namespace nprgl {

// Our exported thunk for a command we know (GL 1.0-2.1 or a window-system call), or null when
// we do not know the name or the driver has no such function: glXGetProcAddress and friends
// then answer what the driver answers.
void* ourProcAddress(const char* name);

} // namespace nprgl
