#pragma once

// Plain data passed between the stages of the geometric strokes pipeline (thesis §4.4):
// extraction -> projection -> visibility -> simplification -> stroke building -> rendering.
// Every stage writes into buffers the caller keeps, so a frame allocates nothing once the
// buffers have grown.

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace nprgl::styles::strokes {

// Connected chains of mesh edges (thesis §4.4.3 SilhouetteLoop). Chain c runs over the mesh
// vertices vertices[vertexStart[c] .. vertexStart[c+1]); a closed chain repeats its first
// vertex at the end. Its segments are edges[vertexStart[c] - c .. vertexStart[c+1] - c - 1).
struct EdgeChains {
    std::vector<uint32_t> vertices;
    std::vector<uint32_t> edges;
    std::vector<uint32_t> vertexStart{0};
    std::vector<uint8_t> closed;

    uint32_t chainCount() const { return uint32_t(closed.size()); }
    uint32_t firstEdge(uint32_t c) const { return vertexStart[c] - c; }
    void clear()
    {
        vertices.clear();
        edges.clear();
        vertexStart.assign(1, 0);
        closed.clear();
    }
};

enum SegmentState : uint8_t { kUnknown = 0, kVisible = 1, kHidden = 2 };

// One point of a projected chain. It lies on the mesh at lerp(va, vb, t) (va == vb for a
// mesh vertex), which is where precomputed per-vertex data (jitter) is looked up.
struct ChainPoint {
    glm::vec3 object{0.0f}; // object space
    glm::vec3 window{0.0f}; // window pixels x, y and depth in [0, 1]
    float w = 1.0f;         // clip w (> 0 in front of the eye)
    float biasedDepth = 0;  // window depth moved towards the eye by the depth tolerance
    uint32_t va = 0, vb = 0;
    float t = 0.0f;
};

// Projected chains or built strokes. Polyline p has points[start[p] .. start[p+1]); the
// segment from point i to i+1 has edge[i] (mesh edge) and state[i]; entries at a polyline's
// last point are unused. A closed polyline repeats its first point at the end.
struct Polylines {
    std::vector<ChainPoint> points;
    std::vector<uint32_t> edge;
    std::vector<uint8_t> state;
    std::vector<uint32_t> start{0};
    std::vector<uint8_t> closed;

    uint32_t count() const { return uint32_t(closed.size()); }
    void clear()
    {
        points.clear();
        edge.clear();
        state.clear();
        start.assign(1, 0);
        closed.clear();
    }
    void addPoint(const ChainPoint& p, uint32_t e, uint8_t s)
    {
        points.push_back(p);
        edge.push_back(e);
        state.push_back(s);
    }
    void endPolyline(bool isClosed)
    {
        start.push_back(uint32_t(points.size()));
        closed.push_back(isClosed ? 1 : 0);
    }
};

// The point at screen fraction s of the segment a -> b, both on mesh edge (e0, e1): window
// position and depth are linear in screen space, the object position follows
// perspective-correct interpolation (1/w is linear on screen).
ChainPoint splitPoint(const ChainPoint& a, const ChainPoint& b, float s, uint32_t e0,
                      uint32_t e1);

// A point's position along mesh edge (e0 -> e1) as a fraction, from its (va, vb, t).
float edgeFraction(const ChainPoint& p, uint32_t e0, uint32_t e1);

} // namespace nprgl::styles::strokes
