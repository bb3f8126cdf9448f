#include "reconstruct/Batch.h"

#include <xxhash.h>

namespace nprgl::reconstruct {

uint64_t hashBatch(const Batch& batch) noexcept
{
    return hashVertices(batch.vertices.data(), batch.vertices.size(), assemblyMode(batch));
}

uint64_t hashVertices(const Vertex* vertices, size_t count, uint32_t mode) noexcept
{
    uint64_t h = XXH3_64bits_withSeed(vertices, count * sizeof(Vertex), mode);
    return h != 0 ? h : 1; // 0 is reserved for "not given"
}

} // namespace nprgl::reconstruct
