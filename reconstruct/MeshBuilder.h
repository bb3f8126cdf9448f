#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "reconstruct/Batch.h"
#include "reconstruct/MeshGeometry.h"
#include "reconstruct/ObjectMesh.h"
#include "reconstruct/ReconstructParams.h"
#include "reconstruct/Welder.h"

namespace nprgl::reconstruct {

// Turns the batches of one object into an ObjectMesh: primitive assembly, welding, OpenMesh
// connectivity (splitting vertices for faces it would refuse), normals and edge classes. Keeps
// scratch buffers between calls; one per thread. Throws std::bad_alloc only.
class MeshBuilder {
public:
    std::shared_ptr<ObjectMesh> build(const Batch* batches, size_t count,
                                      const ReconstructParams& params);

    // True when `object` can show batches[0, count) by moving its vertices: the same modes
    // and vertex counts, the same vertices finite, every vertex still within the weld
    // tolerance of the one it was welded to, and no triangle dropped for zero area now with
    // an area. Vertices that have come together are not merged: the topology stays stable
    // while a mesh animates. Stages the new vertices for applyUpdate().
    bool prepareUpdate(const ObjectMesh& object, const Batch* batches, size_t count,
                       const ReconstructParams& params);
    // Installs the staged vertices and recomputes points, normals and edge classes.
    void applyUpdate(ObjectMesh& object, const Batch* batches, size_t count,
                     const ReconstructParams& params);

private:
    OpenMesh::VertexHandle vertexFor(ObjectMesh& object, uint32_t welded);
    OpenMesh::VertexHandle copyOf(ObjectMesh& object, uint32_t welded);
    void splitFace(ObjectMesh& object, OpenMesh::VertexHandle vh[3]);
    void addFace(ObjectMesh& object, uint32_t f, OpenMesh::VertexHandle vh[3]);
    bool splitFans(ObjectMesh& object);
    void buildEdges(ObjectMesh& object);

    Welder mWelder;
    GeometryScratch mGeometry;
    std::vector<uint32_t> mTriangles;  // kept triangles, source-vertex triples
    std::vector<uint32_t> mMeshVertex; // per welded id: its mesh vertex, or kNoIndex
    std::unordered_map<uint32_t, std::vector<uint32_t>> mCopies; // welded id -> split copies
    std::vector<uint8_t> mBoundaryOut; // per vertex: outgoing boundary halfedges, up to 2
    std::vector<Vertex> mStaged;
};

} // namespace nprgl::reconstruct
