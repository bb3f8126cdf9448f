#include "reconstruct/EdgeLists.h"

namespace nprgl::reconstruct {

void EdgeLists::reset(size_t vertexCount, size_t expectedEdges)
{
    mHead.assign(vertexCount, kNone);
    mDegree.assign(vertexCount, 0);
    mEnds.clear();
    mNext.clear();
    mEnds.reserve(2 * expectedEdges);
    mNext.reserve(2 * expectedEdges);
}

uint32_t EdgeLists::find(uint32_t a, uint32_t b) const
{
    const uint32_t v = mDegree[a] <= mDegree[b] ? a : b;
    const uint32_t other = v == a ? b : a;
    for (uint32_t e = mHead[v]; e != kNone;) {
        const uint32_t side = mEnds[2 * size_t(e)] == v ? 0 : 1;
        if (mEnds[2 * size_t(e) + 1 - side] == other) return e;
        e = mNext[2 * size_t(e) + side];
    }
    return kNone;
}

uint32_t EdgeLists::insert(uint32_t a, uint32_t b)
{
    const uint32_t e = edgeCount();
    mEnds.push_back(a);
    mEnds.push_back(b);
    mNext.push_back(mHead[a]);
    mNext.push_back(mHead[b]);
    mHead[a] = e;
    mHead[b] = e;
    ++mDegree[a];
    ++mDegree[b];
    return e;
}

} // namespace nprgl::reconstruct
