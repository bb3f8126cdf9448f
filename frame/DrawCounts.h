#pragma once

// DrawCounts: how many 3D polygon draws nprgl styled, and how many it left, by reason.

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace nprgl {

// Reasons are the tracker's static strings (StateTracker::unstylableState), compared by
// address. Counting allocates only the first time a reason is seen.
class DrawCounts {
public:
    void noteStyled() { ++mStyled; }
    // Blended passes over geometry styled already (multi-pass surfaces), merged into their
    // object: counted among the styled draws by whoever noted them.
    void noteMerged(uint64_t n) { mMerged += n; }
    // True the first time this reason is counted.
    bool noteLeft(const char* why);
    void clear();
    // What was counted after `earlier` (a copy of these counts taken then).
    DrawCounts since(const DrawCounts& earlier) const;

    uint64_t styled() const { return mStyled; }
    uint64_t merged() const { return mMerged; }
    uint64_t left() const;
    const std::vector<std::pair<const char*, uint64_t>>& leftByReason() const { return mLeft; }
    // "12 styled (2 of them passes merged into their object), 3 left as the program drew
    // them (blending 3)".
    std::string describe() const;

private:
    uint64_t mStyled = 0;
    uint64_t mMerged = 0;
    std::vector<std::pair<const char*, uint64_t>> mLeft;
};

} // namespace nprgl
