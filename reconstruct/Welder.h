#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "reconstruct/Batch.h"

namespace nprgl::reconstruct {

// Welds positions closer than a tolerance in one pass over a spatial hash (no sort). A
// position joins the first earlier welded vertex within the tolerance, else starts a new one,
// so the result is deterministic for a given input order. Keeps its tables between calls.
class Welder {
public:
    // weld[i] = welded id of vertices[i], or kNoIndex where the position is not finite;
    // rep[id] = the first vertex of each id (whose position the id has). [lo, hi] bounds the
    // finite positions. Returns the number of ids. Throws std::bad_alloc only.
    uint32_t weld(const Vertex* vertices, size_t count, const glm::vec3& lo, const glm::vec3& hi,
                  float tolerance, std::vector<uint32_t>& weld, std::vector<uint32_t>& rep);

private:
    uint32_t* findCell(uint64_t key);

    std::vector<uint64_t> mKeys;      // open addressing: cell key, or kEmpty
    std::vector<uint32_t> mHeads;     // first welded id in the cell
    std::vector<uint32_t> mNext;      // per welded id: the next one in its cell
    std::vector<glm::vec3> mPositions; // per welded id
    uint32_t mShift = 64;
};

} // namespace nprgl::reconstruct
