#include "reconstruct/Batch.h"

#include <xxhash.h>

namespace nprgl::reconstruct {

uint64_t hashBatch(const Batch& batch) noexcept
{
    uint64_t h = XXH3_64bits_withSeed(batch.vertices.data(),
                                      batch.vertices.size() * sizeof(Vertex), batch.mode);
    return h != 0 ? h : 1; // 0 is reserved for "not given"
}

} // namespace nprgl::reconstruct
