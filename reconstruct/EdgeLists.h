#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace nprgl::reconstruct {

// The edges of a mesh being connected, found by their endpoints: a list of edges per vertex,
// searched from the endpoint with fewer edges (a fan's centre may have thousands). Edges are
// numbered in insertion order, so the ones a face looks up are recent and in the cache; a
// hash table scattered them and spent 40% of a build in cache misses.
class EdgeLists {
public:
    static constexpr uint32_t kNone = 0xffffffffu;

    // Forgets all edges.
    void reset(size_t vertexCount, size_t expectedEdges);
    void addVertex()
    {
        mHead.push_back(kNone);
        mDegree.push_back(0);
    }
    // The edge between a and b (either direction), or kNone.
    uint32_t find(uint32_t a, uint32_t b) const;
    // A new edge whose halfedge 2e runs a -> b.
    uint32_t insert(uint32_t a, uint32_t b);

    uint32_t edgeCount() const { return uint32_t(mEnds.size() / 2); }
    // Per edge e: ends[2e] -> ends[2e+1] is its halfedge 2e.
    const std::vector<uint32_t>& ends() const { return mEnds; }

private:
    std::vector<uint32_t> mHead;   // per vertex: its latest edge
    std::vector<uint32_t> mDegree; // per vertex
    std::vector<uint32_t> mEnds;   // 2 per edge
    std::vector<uint32_t> mNext;   // 2 per edge: the next edge around ends[2e], ends[2e+1]
};

} // namespace nprgl::reconstruct
