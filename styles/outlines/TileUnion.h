#pragma once

// TileUnion: the union of rectangles on screen, in tiles, as rectangles that do not overlap.

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace nprgl::styles {

// Boxes added over an area are marked in square tiles; rects() gives the marked tiles back as
// few rectangles, none overlapping, so a pass drawn over each covers every box's pixels once
// (the edge operator over a forest of cut-outs' overlapping boxes).
class TileUnion {
public:
    explicit TileUnion(int tile) : mTile(tile) {}

    // Starts over on `area`, [x0, y0, x1, y1) in pixels.
    void reset(const glm::ivec4& area);
    // Marks the tiles box ([x0, y0, x1, y1), within the area) touches; returns the pixels of
    // the tiles it marked that were not marked before.
    int64_t add(const glm::ivec4& box);
    // The marked tiles as rectangles in pixels, clipped to the area: each row's runs of
    // marked tiles, a run grown down while the rows below repeat it.
    const std::vector<glm::ivec4>& rects();

private:
    int mTile;
    glm::ivec4 mArea{0};
    glm::ivec2 mGrid{0};
    std::vector<uint8_t> mMarked;
    std::vector<glm::ivec4> mRects;
    std::vector<size_t> mOpen, mNext; // rects(): runs reaching the row before, and this row
};

} // namespace nprgl::styles
