#include "shim/ProcAddress.h"

#include "shim/Api.h"
#include "shim/RealGl.h"

#include <string_view>
#include <unordered_map>

namespace nprgl {

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
