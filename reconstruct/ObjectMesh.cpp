#include "reconstruct/ObjectMesh.h"

namespace nprgl::reconstruct {

namespace {

template <typename T>
size_t vectorBytes(const std::vector<T>& v)
{
    return v.capacity() * sizeof(T);
}

} // namespace

glm::vec3 ObjectMesh::position(uint32_t v) const
{
    const Mesh::Point& p = mesh.point(OpenMesh::VertexHandle(int(v)));
    return {p[0], p[1], p[2]};
}

glm::vec3 ObjectMesh::vertexNormal(uint32_t v) const
{
    const Mesh::Normal& n = mesh.normal(OpenMesh::VertexHandle(int(v)));
    return {n[0], n[1], n[2]};
}

glm::vec3 ObjectMesh::faceNormal(uint32_t f) const
{
    const Mesh::Normal& n = mesh.normal(OpenMesh::FaceHandle(int(f)));
    return {n[0], n[1], n[2]};
}

uint32_t ObjectMesh::borderEdgeCount() const
{
    uint32_t count = 0;
    for (const uint8_t classes : edgeClasses) count += (classes & kEdgeBorder) ? 1 : 0;
    return count;
}

int64_t ObjectMesh::eulerCharacteristic() const
{
    return int64_t(mesh.n_vertices()) - int64_t(mesh.n_edges()) + int64_t(mesh.n_faces());
}

size_t ObjectMesh::byteSize() const
{
    // OpenMesh arrays: vertex (outgoing halfedge, point, normal), edge (two halfedges of face,
    // vertex, next, prev), face (halfedge, normal).
    size_t bytes = sizeof(*this);
    bytes += mesh.n_vertices() * (4 + sizeof(Mesh::Point) + sizeof(Mesh::Normal));
    bytes += mesh.n_edges() * 2 * 16;
    bytes += mesh.n_faces() * (4 + sizeof(Mesh::Normal));
    bytes += vectorBytes(sourceVertices) + vectorBytes(faceCorners) + vectorBytes(faceVertices);
    bytes += vectorBytes(faceMaterials) + vectorBytes(edges) + vectorBytes(edgeClasses);
    bytes += vectorBytes(vertexEdgeStart);
    bytes += vectorBytes(vertexEdges);
    const UpdateState& u = updateState;
    bytes += vectorBytes(u.batchModes) + vectorBytes(u.batchCounts) + vectorBytes(u.batchFaceEnd);
    bytes += vectorBytes(u.batchMaterials) + vectorBytes(u.weld) + vectorBytes(u.weldRep);
    bytes += vectorBytes(u.weldVertex) + vectorBytes(u.vertexSource);
    bytes += vectorBytes(u.splitVertices) + vectorBytes(u.areaDropped);
    return bytes;
}

} // namespace nprgl::reconstruct
