#pragma once

#include "shim/Context.h"

#include <map>
#include <memory>
#include <mutex>
#include <utility>

namespace nprgl {

// Maps the window system's context handles to nprgl Contexts. Touched only by MakeCurrent and
// DestroyContext, never per GL call, so a mutex is fine here.
class ContextRegistry {
public:
    static ContextRegistry& instance();

    // Makes the context behind handle (created on first use) current on this thread, or
    // releases the thread's context when handle is null.
    void makeCurrent(WindowSystem ws, const void* handle);
    // Forgets the handle. A context still current somewhere lives until it is released there.
    void destroy(WindowSystem ws, const void* handle);

private:
    // At exit: the counts of the contexts the program never destroyed.
    void reportAtExit();

    using Key = std::pair<WindowSystem, const void*>;

    std::mutex mMutex;
    std::map<Key, std::shared_ptr<Context>> mContexts;
    uint32_t mNextSerial = 1;
};

} // namespace nprgl
