#include "shim/ContextRegistry.h"

#include "frame/Compositor.h"
#include "shim/RealGl.h"
#include "shim/Config.h"
#include "shim/ThreadState.h"

#include <cstdlib>

namespace nprgl {

namespace {

// Keeps the thread's current Context alive while the program destroys it on another thread,
// and counts the threads it is current on. A thread's thread-locals go before the atexit
// handlers run (the C++ rules for exit()), so at exit the exiting thread holds none.
struct CurrentContext {
    std::shared_ptr<Context> context;
    void set(std::shared_ptr<Context> next)
    {
        if (next == context) return;
        if (context) context->noteCurrent(-1);
        if (next) next->noteCurrent(1);
        context = std::move(next);
    }
    ~CurrentContext() { set(nullptr); }
};
thread_local CurrentContext tCurrent;

} // namespace

ContextRegistry& ContextRegistry::instance()
{
    static ContextRegistry* registry = [] {
        auto* r = new ContextRegistry; // never destroyed: exit-safe
        std::atexit([] { instance().reportAtExit(); });
        return r;
    }();
    return *registry;
}

void ContextRegistry::reportAtExit()
{
    // Not waiting: exit() called by a thread holding the lock would never return.
    std::unique_lock lock(mMutex, std::try_to_lock);
    if (!lock.owns_lock()) return;
    for (auto& [key, ctx] : mContexts) {
        Compositor* c = ctx->compositor();
        if (!c) continue;
        // Current on a thread still running (a render thread the program did not stop): its
        // counts may be changing; the copy taken at its last frame end is not.
        if (ctx->threadsCurrent() == 0) c->reportRunCounts();
        else c->reportRunCountsAtFrameEnd();
    }
}

void ContextRegistry::makeCurrent(WindowSystem ws, const void* handle)
{
    if (!handle) {
        tCurrent.set(nullptr);
        tThread.context = nullptr;
        tThread.dispatch = &gRealGl;
        return;
    }
    // Read (and reported) once, at the first context; every context gets the same.
    const Config& config = Config::process();
    std::shared_ptr<Context> ctx;
    {
        std::lock_guard lock(mMutex);
        auto& slot = mContexts[Key{ws, handle}];
        if (!slot) slot = std::make_shared<Context>(ws, handle, mNextSerial++, config);
        ctx = slot;
    }
    tCurrent.set(ctx);
    tThread.context = ctx.get();
    tThread.dispatch = &ctx->dispatch();
    ctx->onMakeCurrent();
}

void ContextRegistry::destroy(WindowSystem ws, const void* handle)
{
    std::lock_guard lock(mMutex);
    mContexts.erase(Key{ws, handle});
}

} // namespace nprgl
