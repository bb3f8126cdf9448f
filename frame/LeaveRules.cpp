#include "frame/LeaveRules.h"

#include "styles/Scene.h"

#include <algorithm>
#include <bit>

namespace nprgl {

namespace {

constexpr struct {
    uint32_t bit;
    const char* name;
} kStates[] = {{kLeaveTranslucent, "translucent"},
               {kLeaveCutout, "cutout"},
               {kLeaveDecal, "decal"},
               {kLeaveBackdrop, "backdrop"}};

} // namespace

void LeaveRules::normalise()
{
    std::sort(textures.begin(), textures.end());
    textures.erase(std::unique(textures.begin(), textures.end()), textures.end());
}

bool LeaveRules::leavesTexture(uint64_t hash) const
{
    return hash != 0 && std::binary_search(textures.begin(), textures.end(), hash);
}

size_t LeaveRules::count() const { return textures.size() + size_t(std::popcount(states)); }

uint32_t LeaveRules::stateBit(const std::string& name)
{
    for (const auto& s : kStates) {
        if (name == s.name) return s.bit;
    }
    return 0;
}

const char* LeaveRules::stateName(uint32_t bit)
{
    for (const auto& s : kStates) {
        if (bit == s.bit) return s.name;
    }
    return "";
}

std::string LeaveRules::stateNames(uint32_t states, const char* separator)
{
    std::string names;
    for (const auto& s : kStates) {
        if (!(states & s.bit)) continue;
        if (!names.empty()) names += separator;
        names += s.name;
    }
    return names;
}

uint32_t LeaveRules::statesOf(const styles::SceneObject& o)
{
    uint32_t states = 0;
    if (o.translucent) states |= kLeaveTranslucent;
    if (o.alphaFunc != GL_ALWAYS) states |= kLeaveCutout;
    if (o.offsetFactor != 0.0f || o.offsetUnits != 0.0f) states |= kLeaveDecal;
    if (!o.depthTest && !o.orthographic()) states |= kLeaveBackdrop;
    return states;
}

} // namespace nprgl
