#include "shim/ProcAddress.h"

#include "shim/Api.h"
#include "shim/RealGl.h"

#include <string_view>
#include <unordered_map>

namespace nprgl {

const ApiAlias kGlAliases[] = {
#define NPRGL_GL_ALIAS(ret, name, params, args, core)                                          \
    {#name, reinterpret_cast<void*>(&::name), #core},
#include "nprgl_api.inc"
};
const size_t kGlAliasCount = sizeof kGlAliases / sizeof kGlAliases[0];

namespace {

struct Slot {
    void* thunk;
    size_t index;
    bool gl;
};

const std::unordered_map<std::string_view, Slot>& table()
{
    static const auto* map = [] {
        auto* m = new std::unordered_map<std::string_view, Slot>;
        for (size_t i = 0; i < kGlEntryCount; ++i) {
            m->emplace(kGlEntries[i].name, Slot{kGlEntries[i].thunk, i, true});
        }
        for (size_t i = 0; i < kWsEntryCount; ++i) {
            m->emplace(kWsEntries[i].name, Slot{kWsEntries[i].thunk, i, false});
        }
        // An alias answers when its command has a real function (the thunk calls that).
        for (size_t i = 0; i < kGlAliasCount; ++i) {
            auto core = m->find(kGlAliases[i].core);
            if (core == m->end()) continue;
            m->emplace(kGlAliases[i].name, Slot{kGlAliases[i].thunk, core->second.index, true});
        }
        return m;
    }();
    return *map;
}

} // namespace

void* ourProcAddress(const char* name)
{
    if (!name) return nullptr;
    const auto& map = table();
    auto it = map.find(name);
    if (it == map.end()) return nullptr;
    const Slot& slot = it->second;
    bool found = slot.gl ? realGlFound(slot.index) : realWsFound(slot.index);
    return found ? slot.thunk : nullptr;
}

} // namespace nprgl
