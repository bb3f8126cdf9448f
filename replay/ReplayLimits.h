#pragma once

// ReplayLimits: how much work and memory one replayed call (or a whole replay) may ask of
// the driver before the replayer refuses it.

#include <cstdint>

namespace nprgl {

// The defaults are far above what real programs record; the fuzz target sets small ones so
// that every input runs in bounded time and memory.
struct ReplayLimits {
    uint64_t drawVertices = uint64_t(1) << 26; // vertices (or indices) of one draw
    uint64_t listWork = uint64_t(1) << 30;     // calls and vertices one glCallList(s) runs
    uint64_t names = uint64_t(1) << 22;        // glGen*, glGenLists, glDeleteLists counts
    uint64_t texels = uint64_t(1) << 28;       // one texture image
    uint64_t bufferBytes = uint64_t(1) << 31;  // one glBufferData
    uint64_t totalBytes = 0; // textures and buffers allocated in a whole replay (0: no limit)
    uint64_t totalWork = 0;  // vertices drawn and list work in a whole replay (0: no limit)
};

} // namespace nprgl
