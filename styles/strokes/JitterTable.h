#pragma once

#include "reconstruct/ObjectMesh.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace nprgl::styles::strokes {

// Per-vertex random offsets for the sketchy overdraw passes (thesis §4.4.7), made once per
// mesh and kept with it, so the same vertex wobbles the same way in every frame and nothing
// flickers. Values are uniform in [-1, 1]^3 (tangent, view, normal axes of the local frame),
// from a hash of (seed, pass, vertex): the same mesh always gets the same wobble.
class JitterTable {
public:
    // passes * vertexCount offsets, pass-major. Valid until the next call.
    const glm::vec3* offsets(const reconstruct::ObjectMesh& mesh, uint32_t passes,
                             uint32_t seed);
    // Once per frame: forgets meshes not used for a while (their pointers may be reused).
    void endFrame();
    size_t size() const { return mEntries.size(); }

    static glm::vec3 offset(uint32_t seed, uint32_t pass, uint32_t vertex);

private:
    struct Entry {
        uint64_t contentKey = 0;
        uint32_t vertices = 0, passes = 0, seed = 0;
        uint64_t lastUsed = 0;
        std::vector<glm::vec3> values;
    };
    std::unordered_map<const reconstruct::ObjectMesh*, Entry> mEntries;
    uint64_t mFrame = 0;
};

} // namespace nprgl::styles::strokes
