#pragma once

#include <cstddef>
#include <vector>

#include <glm/glm.hpp>

#include "reconstruct/ObjectMesh.h"

namespace nprgl::reconstruct {

// Per mesh vertex, gathered from the source vertices before computeGeometry: its position and
// the sum of the normals the program gave at the source vertices welded into it. Reused
// between calls (points is swapped with the mesh's, so neither side allocates per frame).
struct GeometryScratch {
    std::vector<Mesh::Point> points;
    std::vector<glm::vec3> givenSum;
    std::vector<glm::vec3> areaSum;
    // Source vertices gathered without a normal; at 0 no area-weighted sums are needed.
    size_t missingNormals = 0;

    // Sizes points and givenSum for `vertexCount` vertices (givenSum zeroed).
    void prepare(size_t vertexCount);
    // Source vertex i (welded id w, see ObjectMesh::UpdateState) contributes: the position of
    // its welded vertex if it is the id's representative, and its normal if it has one.
    void add(const ObjectMesh::UpdateState& state, const Vertex& source, uint32_t i, uint32_t w)
    {
        const uint32_t v = state.weldVertex[w];
        if (v == kNoIndex) return; // only in dropped triangles
        if (state.weldRep[w] == i) {
            const glm::vec3& p = source.position;
            points[v] = Mesh::Point(p.x, p.y, p.z);
        }
        if (source.hasNormal) givenSum[v] += source.normal;
        else ++missingNormals;
    }
    // Vertices split off for non-manifold faces: the position and normal of their source.
    void addSplitVertices(const ObjectMesh::UpdateState& state, const Vertex* sources);
};

// Gathers every source vertex of `object` into scratch (a full build).
void gatherSources(const ObjectMesh& object, GeometryScratch& scratch);

// Installs scratch.points as the mesh's points and computes unit face normals, vertex normals
// (normalised sum of the program's normals where it gave any, else of area-weighted face
// normals) and the crease and material bits of the edges. Connectivity is not touched.
void computeGeometry(ObjectMesh& object, float creaseCosine, GeometryScratch& scratch);

} // namespace nprgl::reconstruct
