#include "stream/OpcodeMap.h"

#include "stream/Opcodes.h"

#include <string_view>
#include <unordered_map>

namespace nprgl {

static_assert(op::kFrameEnd == 0xFF00 && op::kCount < OpcodeMap::kUnknown);

OpcodeMap::OpcodeMap(const std::vector<std::string>& names) : mNames(names)
{
    static const auto byName = [] {
        std::unordered_map<std::string_view, uint16_t> m;
        for (uint16_t i = 0; i < op::kCount; ++i) m.emplace(kOpcodeNames[i], i);
        return m;
    }();
    bool same = names.size() <= op::kCount;
    mMap.resize(names.size(), kUnknown);
    for (size_t i = 0; i < names.size(); ++i) {
        auto it = byName.find(names[i]);
        if (it == byName.end()) {
            ++mUnknown;
            same = false;
            continue;
        }
        mMap[i] = it->second;
        same = same && it->second == i;
    }
    if (same) mMap.clear(); // the common case: a file written by this build
}

std::string OpcodeMap::unknown(uint16_t fileOpcode) const
{
    if (fileOpcode < mNames.size()) {
        return "the capture's " + mNames[fileOpcode] + " (opcode " +
               std::to_string(fileOpcode) + ") is not a command this nprgl knows";
    }
    return "opcode " + std::to_string(fileOpcode) + " is not in the capture's table of " +
           std::to_string(mNames.size()) + " commands";
}

} // namespace nprgl
