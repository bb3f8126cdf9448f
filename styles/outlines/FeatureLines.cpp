#include "styles/outlines/FeatureLines.h"

#include <glm/glm.hpp>

namespace nprgl::styles {

namespace {

// Faces closer than this in orientation (about 0.8 degrees) are one plane: no fold between
// them can turn into a silhouette or a crease.
constexpr float kCoplanarCosine = 0.9999f;

// The corner of face f at mesh vertex v, or kNoIndex.
uint32_t cornerAt(const reconstruct::ObjectMesh& mesh, uint32_t f, uint32_t v)
{
    for (int k = 0; k < 3; ++k) {
        if (mesh.faceVertices[3 * size_t(f) + k] == v) return mesh.faceCorners[3 * size_t(f) + k];
    }
    return reconstruct::kNoIndex;
}

// Whether two corners at one point draw the same: the operator sees their normals and colours.
bool sameCorner(const reconstruct::ObjectMesh& mesh, uint32_t a, uint32_t b)
{
    if (a == b) return true;
    const reconstruct::Vertex& p = mesh.sourceVertices[a];
    const reconstruct::Vertex& q = mesh.sourceVertices[b];
    return p.hasNormal == q.hasNormal && (!p.hasNormal || p.normal == q.normal) &&
           p.color == q.color;
}

} // namespace

void FeatureLines::collect(const reconstruct::ObjectMesh& mesh, std::vector<uint32_t>& pairs)
{
    using reconstruct::kNoIndex;
    const uint32_t faces = mesh.faceCount();
    if (mesh.faceCorners.size() < 3 * size_t(faces) ||
        mesh.faceVertices.size() < 3 * size_t(faces)) {
        return;
    }
    if (mesh.edges.empty()) {
        // No connectivity to judge by: every edge of every face.
        for (uint32_t f = 0; f < faces; ++f) {
            for (int k = 0; k < 3; ++k) {
                pairs.push_back(mesh.faceCorners[3 * size_t(f) + k]);
                pairs.push_back(mesh.faceCorners[3 * size_t(f) + (k + 1) % 3]);
            }
        }
        return;
    }
    for (const reconstruct::EdgeInfo& e : mesh.edges) {
        const bool has0 = e.f0 < faces, has1 = e.f1 < faces;
        if (!has0 && !has1) continue;
        const uint32_t f = has0 ? e.f0 : e.f1;
        const uint32_t a = cornerAt(mesh, f, e.v0), b = cornerAt(mesh, f, e.v1);
        if (a == kNoIndex || b == kNoIndex) continue;
        bool feature = !has0 || !has1;
        if (!feature) {
            const glm::vec3 n0 = mesh.faceNormal(e.f0), n1 = mesh.faceNormal(e.f1);
            // A degenerate face's zero normal says nothing: keep the edge.
            feature = glm::dot(n0, n1) < kCoplanarCosine ||
                      mesh.faceMaterials[e.f0] != mesh.faceMaterials[e.f1];
        }
        if (!feature) {
            const uint32_t c = cornerAt(mesh, e.f1, e.v0), d = cornerAt(mesh, e.f1, e.v1);
            feature = c == kNoIndex || d == kNoIndex || !sameCorner(mesh, a, c) ||
                      !sameCorner(mesh, b, d);
        }
        if (!feature) continue;
        pairs.push_back(a);
        pairs.push_back(b);
    }
}

} // namespace nprgl::styles
