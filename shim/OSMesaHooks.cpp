#include "shim/Context.h"
#include "shim/ContextRegistry.h"
#include "shim/ProcAddress.h"
#include "shim/RealGl.h"
#include "shim/ThreadState.h"

// OSMesa: context life. Its frames end at glFinish (see Context).

namespace nprgl::hooks {

GLboolean OSMesaMakeCurrent(OSMesaContext ctx, void* buffer, GLenum type, GLsizei width,
                            GLsizei height)
{
    if (Context* current = tThread.context) current->release();
    GLboolean ok = gRealWs.OSMesaMakeCurrent(ctx, buffer, type, width, height);
    if (ok) {
        ContextRegistry::instance().makeCurrent(WindowSystem::OSMesa, ctx);
        if (Context* c = tThread.context) c->setDrawableSize(width, height);
    }
    return ok;
}

void OSMesaDestroyContext(OSMesaContext ctx)
{
    gRealWs.OSMesaDestroyContext(ctx);
    ContextRegistry::instance().destroy(WindowSystem::OSMesa, ctx);
}

OSMESAproc OSMesaGetProcAddress(const char* name)
{
    if (void* thunk = ourProcAddress(name)) return reinterpret_cast<OSMESAproc>(thunk);
    return gRealWs.OSMesaGetProcAddress(name);
}

} // namespace nprgl::hooks
