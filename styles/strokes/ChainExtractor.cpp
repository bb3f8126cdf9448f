#include "styles/strokes/ChainExtractor.h"

#include <algorithm>

namespace nprgl::styles::strokes {

using reconstruct::EdgeInfo;
using reconstruct::kNoIndex;
using reconstruct::Mesh;

namespace {

constexpr uint8_t kVisited = 0x80;
constexpr uint8_t kSilhouette = 1;
constexpr uint8_t kOther = 2;

inline glm::vec3 toGlm(const Mesh::Point& p) { return {p[0], p[1], p[2]}; }

inline float facing(const Mesh::Normal& n, const glm::vec3& view)
{
    return n[0] * view.x + n[1] * view.y + n[2] * view.z;
}

} // namespace

void ChainExtractor::extract(const reconstruct::ObjectMesh& mesh, const glm::vec3& eye,
                             const Options& options, EdgeChains& out)
{
    out.clear();
    const uint32_t edgeCount = mesh.edgeCount();
    mMark.assign(edgeCount, 0);
    mSelected.clear();
    mSilhouettes = 0;
    const Mesh::Point* points = mesh.mesh.points();
    const Mesh::Normal* normals = mesh.mesh.property(mesh.mesh.face_normals_pph()).data();
    const bool wantCreases = options.creases, wantBorders = options.borders;
    const bool haveClasses = mesh.edgeClasses.size() == edgeCount;

    // Eq. 4.1 with the eye already in object space: one dot product per adjacent face.
    for (uint32_t e = 0; e < edgeCount; ++e) {
        const EdgeInfo& info = mesh.edges[e];
        uint8_t mark = 0;
        if (info.f0 != kNoIndex && info.f1 != kNoIndex) {
            const Mesh::Point& a = points[info.v0];
            const Mesh::Point& b = points[info.v1];
            const glm::vec3 view = eye - 0.5f * (toGlm(a) + toGlm(b));
            const float d0 = facing(normals[info.f0], view);
            const float d1 = facing(normals[info.f1], view);
            if ((d0 < 0.0f && d1 > 0.0f) || (d0 > 0.0f && d1 < 0.0f)) mark = kSilhouette;
        }
        if (!mark && haveClasses) {
            const uint8_t classes = mesh.edgeClasses[e];
            if ((wantCreases && (classes & reconstruct::kEdgeCrease)) ||
                (wantBorders && (classes & reconstruct::kEdgeBorder)))
                mark = kOther;
        }
        if (mark) {
            mMark[e] = mark;
            mSelected.push_back(e);
            mSilhouettes += mark == kSilhouette ? 1 : 0;
        }
    }

    for (uint8_t pass : {kSilhouette, kOther}) {
        for (uint32_t e : mSelected) {
            if (mMark[e] != pass) continue; // other class, or already in a chain
            mMark[e] |= kVisited;
            const EdgeInfo& info = mesh.edges[e];
            const glm::vec3 a = toGlm(points[info.v0]), b = toGlm(points[info.v1]);
            mForwardVertices.assign({info.v0, info.v1});
            mForwardEdges.assign({e});
            mBackVertices.clear();
            mBackEdges.clear();
            bool closed = walk(mesh, info.v1, info.v0, b - a, pass, mForwardVertices,
                               mForwardEdges);
            if (!closed) walk(mesh, info.v0, kNoIndex, a - b, pass, mBackVertices, mBackEdges);
            // Backward part reversed in front of the forward part.
            out.vertices.insert(out.vertices.end(), mBackVertices.rbegin(),
                                mBackVertices.rend());
            out.vertices.insert(out.vertices.end(), mForwardVertices.begin(),
                                mForwardVertices.end());
            out.edges.insert(out.edges.end(), mBackEdges.rbegin(), mBackEdges.rend());
            out.edges.insert(out.edges.end(), mForwardEdges.begin(), mForwardEdges.end());
            out.vertexStart.push_back(uint32_t(out.vertices.size()));
            out.closed.push_back(closed ? 1 : 0);
        }
    }
}

bool ChainExtractor::walk(const reconstruct::ObjectMesh& mesh, uint32_t from, uint32_t stop,
                          glm::vec3 direction, uint8_t pass, std::vector<uint32_t>& vertices,
                          std::vector<uint32_t>& edges)
{
    const Mesh::Point* points = mesh.mesh.points();
    uint32_t current = from;
    for (;;) {
        const glm::vec3 here = toGlm(points[current]);
        const float dirLength = glm::length(direction);
        uint32_t best = kNoIndex, bestVertex = 0;
        float bestScore = -2.0f;
        glm::vec3 bestDirection(0.0f);
        for (uint32_t k = mesh.vertexEdgeStart[current]; k < mesh.vertexEdgeStart[current + 1];
             ++k) {
            const uint32_t e = mesh.vertexEdges[k];
            if (mMark[e] != pass) continue;
            const EdgeInfo& info = mesh.edges[e];
            const uint32_t other = info.v0 == current ? info.v1 : info.v0;
            const glm::vec3 d = toGlm(points[other]) - here;
            const float len = glm::length(d);
            // Straightest continuation; closing the loop wins ties.
            float score = (len > 0.0f && dirLength > 0.0f)
                              ? glm::dot(d, direction) / (len * dirLength)
                              : -1.0f;
            if (other == stop) score += 1e-4f;
            if (score > bestScore) {
                bestScore = score;
                best = e;
                bestVertex = other;
                bestDirection = d;
            }
        }
        if (best == kNoIndex) return false;
        mMark[best] |= kVisited;
        edges.push_back(best);
        vertices.push_back(bestVertex);
        if (bestVertex == stop) return true;
        current = bestVertex;
        direction = bestDirection;
    }
}

} // namespace nprgl::styles::strokes
