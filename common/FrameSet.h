#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace nprgl {

// A set of frame numbers (counted from 1) written as "1,10,100", "1-5,9" or "20-" (open end).
class FrameSet {
public:
    // Parses text; on failure returns false and says why in error.
    static bool parse(std::string_view text, FrameSet& out, std::string& error);
    // Frames (ascending) in the syntax parse reads: "1-3,7".
    static std::string describe(const std::vector<uint64_t>& frames);

    bool contains(uint64_t frame) const;
    bool empty() const { return mRanges.empty(); }
    // The last frame in the set, or UINT64_MAX when a range is open.
    uint64_t last() const;

private:
    struct Range {
        uint64_t first;
        uint64_t last;
    };
    std::vector<Range> mRanges;
};

} // namespace nprgl
