// Library start-up: only what must happen before the program's first call. Nothing is
// printed and nothing is resolved here, so programs that never use GL see no difference.

#include "common/Log.h"
#include "frame/CaptureSession.h"

namespace {

__attribute__((constructor)) void nprglInit()
{
    nprgl::initLog();
    // Reads NPRGL_RECORD and notes this process's pid before the program can fork.
    nprgl::CaptureSession::instance();
}

} // namespace
