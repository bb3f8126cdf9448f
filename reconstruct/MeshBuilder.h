#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "reconstruct/Batch.h"
#include "reconstruct/EdgeLists.h"
#include "reconstruct/MeshGeometry.h"
#include "reconstruct/ObjectMesh.h"
#include "reconstruct/ReconstructParams.h"
#include "reconstruct/Welder.h"

namespace nprgl::reconstruct {

// Turns the batches of one object into an ObjectMesh: primitive assembly, welding, OpenMesh
// connectivity, normals and edge classes. Non-manifold input keeps every face: faces beyond
// an edge's manifold pair (a third sheet, a flipped or duplicated face) are cut off along it,
// and a vertex where several fans of faces meet (a bow-tie) is copied once per extra fan;
// BuildStats counts both (cutNonManifold()).
//
// The connectivity is written straight into OpenMesh's arrays for the whole mesh at once
// (the same halfedge structure add_face makes, boundary loops included): Debian builds
// OpenMesh with assertions, which made add_face half of the build time.
//
// Keeps scratch buffers between calls; one per thread. Throws std::bad_alloc only.
class MeshBuilder {
public:
    std::shared_ptr<ObjectMesh> build(const Batch* batches, size_t count,
                                      const ReconstructParams& params);

    // True when `object` can show batches[0, count) by moving its vertices: the same modes
    // and vertex counts, the same vertices finite, every vertex still within the build's weld
    // tolerance of the one it was welded to, and no triangle dropped for zero area now with
    // an area. Vertices that have come together are not merged: the topology stays stable
    // while a mesh animates. Stages the new vertices, positions and normals for applyUpdate();
    // does not touch `object`.
    bool prepareUpdate(const ObjectMesh& object, const Batch* batches, size_t count);
    // Installs what prepareUpdate staged and recomputes normals and edge classes. Does not
    // allocate, so running out of memory cannot leave `object` half updated.
    void applyUpdate(ObjectMesh& object, const Batch* batches, size_t count,
                     const ReconstructParams& params);

private:
    uint32_t vertexFor(ObjectMesh& object, uint32_t welded);
    uint32_t copyVertex(ObjectMesh& object, uint32_t v);
    uint32_t halfedgeOf(uint32_t from, uint32_t to) const;
    unsigned conflicts(const uint32_t v[3]) const;
    void placeFace(ObjectMesh& object, uint32_t f, uint32_t v[3]);
    void fillMesh(ObjectMesh& object);
    bool linkBoundaries(ObjectMesh& object);
    bool connectFast(ObjectMesh& object);
    void cutNonManifold(ObjectMesh& object);
    void splitFans(ObjectMesh& object, bool everyFace);
    void connect(ObjectMesh& object);
    void buildEdges(ObjectMesh& object);

    Welder mWelder;
    GeometryScratch mGeometry;
    EdgeLists mEdges;
    std::vector<uint32_t> mTriangles;     // kept triangles, source-vertex triples
    std::vector<uint8_t> mEdgeUsed;       // per edge: bit i = halfedge 2e+i has a face
    std::vector<uint32_t> mFaceHalfedges; // 3 per face
    std::vector<uint32_t> mCornerCount;   // per vertex
    std::vector<uint32_t> mOutBoundary;   // per vertex: its outgoing boundary halfedge
    std::vector<uint32_t> mFanVertices;   // vertices where several fans meet
    std::vector<Vertex> mStaged;
};

} // namespace nprgl::reconstruct
