#pragma once

// LeaveRules: which draws the user's rules leave as the program draws them (by texture content
// and by draw state), as configuration files, the overlay and replays give them.

#include <cstdint>
#include <string>
#include <vector>

namespace nprgl::styles {
struct SceneObject;
}

namespace nprgl {

// The draw states a rule (leave_state=) may name, as bits.
enum LeftState : uint32_t {
    kLeaveTranslucent = 1u << 0, // blended by its alpha (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)
    kLeaveCutout = 1u << 1,      // the alpha test on
    kLeaveDecal = 1u << 2,       // GL_POLYGON_OFFSET_FILL on
    kLeaveBackdrop = 1u << 3,    // 3D (a perspective view) without the depth test
};

struct LeaveRules {
    std::vector<uint64_t> textures; // texture content hashes (StateTracker::textureHash), sorted
    uint32_t states = 0;            // LeftState bits

    // Sorts the hashes and drops repeats.
    void normalise();
    bool leavesTexture(uint64_t hash) const;
    size_t count() const;
    bool operator==(const LeaveRules&) const = default;

    // A state's name as leave_state= writes it ("translucent"...), and back (0: no state).
    static uint32_t stateBit(const std::string& name);
    static const char* stateName(uint32_t bit);
    // The names of `states`' bits, in bit order, joined by `separator`.
    static std::string stateNames(uint32_t states, const char* separator = ", ");
    // The states an object of a held scene was drawn in (what a state rule would leave).
    static uint32_t statesOf(const styles::SceneObject& object);
};

} // namespace nprgl
