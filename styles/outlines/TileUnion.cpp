#include "styles/outlines/TileUnion.h"

#include <algorithm>

namespace nprgl::styles {

void TileUnion::reset(const glm::ivec4& area)
{
    mArea = area;
    mGrid = glm::max(glm::ivec2(0), (glm::ivec2(area.z, area.w) - glm::ivec2(area) + mTile - 1) /
                                        mTile);
    mMarked.assign(size_t(mGrid.x) * size_t(mGrid.y), 0);
}

int64_t TileUnion::add(const glm::ivec4& box)
{
    const glm::ivec4 b(glm::max(glm::ivec2(box), glm::ivec2(mArea)),
                       glm::min(glm::ivec2(box.z, box.w), glm::ivec2(mArea.z, mArea.w)));
    if (b.x >= b.z || b.y >= b.w) return 0;
    const glm::ivec2 lo = (glm::ivec2(b) - glm::ivec2(mArea)) / mTile;
    const glm::ivec2 hi = (glm::ivec2(b.z, b.w) - glm::ivec2(mArea) - 1) / mTile;
    int64_t added = 0;
    for (int y = lo.y; y <= hi.y; ++y) {
        for (int x = lo.x; x <= hi.x; ++x) {
            uint8_t& tile = mMarked[size_t(y) * size_t(mGrid.x) + size_t(x)];
            added += tile == 0;
            tile = 1;
        }
    }
    return added * mTile * mTile;
}

const std::vector<glm::ivec4>& TileUnion::rects()
{
    mRects.clear();
    mOpen.clear();
    for (int y = 0; y < mGrid.y; ++y) {
        mNext.clear();
        const uint8_t* row = &mMarked[size_t(y) * size_t(mGrid.x)];
        for (int x = 0; x < mGrid.x;) {
            if (!row[x]) {
                ++x;
                continue;
            }
            const int start = x;
            while (x < mGrid.x && row[x]) ++x;
            auto same = std::find_if(mOpen.begin(), mOpen.end(), [&](size_t r) {
                return mRects[r].x == start && mRects[r].z == x;
            });
            if (same != mOpen.end()) {
                mRects[*same].w = y + 1;
                mNext.push_back(*same);
            } else {
                mRects.push_back({start, y, x, y + 1});
                mNext.push_back(mRects.size() - 1);
            }
        }
        std::swap(mOpen, mNext);
    }
    for (glm::ivec4& r : mRects) {
        r = glm::ivec4(mArea.x + r.x * mTile, mArea.y + r.y * mTile,
                       std::min(mArea.x + r.z * mTile, mArea.z),
                       std::min(mArea.y + r.w * mTile, mArea.w));
    }
    return mRects;
}

} // namespace nprgl::styles
