#pragma once

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

namespace nprgl::reconstruct {

// Vertex and face normals are standard properties, always present; no status bits (nothing
// is ever deleted, a mesh is rebuilt instead).
struct MeshTraits : public OpenMesh::DefaultTraits {
    VertexAttributes(OpenMesh::Attributes::Normal);
    FaceAttributes(OpenMesh::Attributes::Normal);
    HalfedgeAttributes(OpenMesh::Attributes::PrevHalfedge);
};

using Mesh = OpenMesh::TriMesh_ArrayKernelT<MeshTraits>;

} // namespace nprgl::reconstruct
