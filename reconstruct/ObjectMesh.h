#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "reconstruct/Batch.h"
#include "reconstruct/Mesh.h"

namespace nprgl::reconstruct {

using EdgeIndex = uint32_t;
inline constexpr uint32_t kNoIndex = 0xffffffffu;

// Bits of ObjectMesh::edgeClasses (thesis §4.1.1). Silhouettes depend on the eye: Silhouette.h.
enum EdgeClass : uint8_t {
    kEdgeBorder = 1,   // one face only
    kEdgeCrease = 2,   // interior, n1·n2 < ReconstructParams::creaseCosine (both normals valid)
    kEdgeMaterial = 4, // interior, the two faces' material ids differ
};

// One mesh edge, indexed like the OpenMesh edge (its halfedges are 2e and 2e+1).
struct EdgeInfo {
    uint32_t v0 = 0;        // halfedge 2e runs v0 -> v1
    uint32_t v1 = 0;
    uint32_t f0 = kNoIndex; // face of halfedge 2e (v0 -> v1 in its winding), or kNoIndex
    uint32_t f1 = kNoIndex; // face of halfedge 2e+1, or kNoIndex
};

// What happened to the object's input at its last full build.
struct BuildStats {
    uint32_t batches = 0;
    uint32_t sourceVertices = 0;      // all vertices of all batches
    uint32_t incompleteVertices = 0;  // trailing vertices that make no primitive (GL drops them)
    uint32_t triangles = 0;           // assembled, before anything was dropped
    uint32_t nonFiniteTriangles = 0;  // dropped: a corner position is NaN or infinite
    uint32_t degenerateTriangles = 0; // dropped: two corners welded together, or zero area
    uint32_t weldedVertices = 0;      // distinct finite positions after welding
    uint32_t splitFaces = 0;          // faces moved onto vertex copies (non-manifold input)
    uint32_t splitVertices = 0;       // vertex copies made for them
};

// One object: the welded triangle mesh of consecutive batches drawn with one modelview, in
// object space. Faces keep the GL's winding and the order the program drew them in. Corner k
// of face f (k = 0, 1, 2) is faceVertices[3f+k]; OpenMesh's halfedge_handle(fh) points to
// corner 0 and next_halfedge_handle walks 1, 2. Normals, colours and texcoords stay per
// corner (corner()), so hard edges keep their shading.
//
// Meshes come from the Reconstructor as shared_ptr<const ObjectMesh>. Hold the pointer while
// you use the mesh: one that only the cache holds may be updated in place by a later frame
// (geometryVersion then changes, the topology never does).
struct ObjectMesh {
    // Connectivity, points, vertex normals (the program's: the normalised sum of the normals
    // it gave at the source vertices welded into the vertex; where it gave none, area-weighted
    // face normals) and unit face normals (0 for a face that became degenerate in an update).
    Mesh mesh;
    std::vector<Vertex> sourceVertices;  // the batches' vertices, concatenated
    std::vector<uint32_t> faceCorners;   // 3 per face: index into sourceVertices
    std::vector<uint32_t> faceVertices;  // 3 per face: mesh vertex index
    std::vector<uint32_t> faceMaterials; // per face: its batch's materialId
    std::vector<EdgeInfo> edges;         // per OpenMesh edge; fixed with the topology
    std::vector<uint8_t> edgeClasses;    // per edge: EdgeClass bits (crease, material: per frame)
    // Edges around each vertex (thesis §4.4.2's per-endpoint neighbour lists):
    // vertexEdges[vertexEdgeStart[v] .. vertexEdgeStart[v+1]).
    std::vector<uint32_t> vertexEdgeStart;
    std::vector<uint32_t> vertexEdges;
    BuildStats stats;
    uint64_t contentKey = 0;      // the content of the batches this mesh shows
    uint32_t geometryVersion = 0; // +1 at each in-place update

    uint32_t vertexCount() const { return uint32_t(mesh.n_vertices()); }
    uint32_t edgeCount() const { return uint32_t(edges.size()); }
    uint32_t faceCount() const { return uint32_t(faceMaterials.size()); }
    glm::vec3 position(uint32_t v) const;
    glm::vec3 vertexNormal(uint32_t v) const;
    glm::vec3 faceNormal(uint32_t f) const;
    const Vertex& corner(uint32_t f, int k) const { return sourceVertices[faceCorners[3 * f + k]]; }
    uint32_t borderEdgeCount() const;
    bool closed() const { return borderEdgeCount() == 0; }
    // V - E + F: 2 for a closed sphere-like mesh, 0 for a torus.
    int64_t eulerCharacteristic() const;
    // Approximate heap bytes, for the cache's budget.
    size_t byteSize() const;

    // Internal to the Reconstructor: what updating moved positions without rebuilding needs.
    struct UpdateState {
        std::vector<uint32_t> batchModes;     // per batch
        std::vector<uint32_t> batchCounts;    // per batch: vertex count
        std::vector<uint32_t> batchMaterials; // per batch
        std::vector<uint32_t> batchFaceEnd;   // per batch: one past its last face
        std::vector<uint32_t> weld;           // per source vertex: welded id; kNoIndex: not finite
        std::vector<uint32_t> weldRep;        // per welded id: its first source vertex
        std::vector<uint32_t> weldVertex;     // per welded id: its mesh vertex, or kNoIndex
        std::vector<uint32_t> vertexSource;   // per mesh vertex: the source of its position
        std::vector<uint32_t> splitVertices;  // mesh vertices that are copies (non-manifold)
        std::vector<uint32_t> areaDropped;    // source-vertex triples dropped for zero area
        float weldTolerance = 0.0f;           // absolute, at the build
        float updateTolerance = 0.0f;         // absolute: welded corners may drift this far
    } updateState;
};

} // namespace nprgl::reconstruct
