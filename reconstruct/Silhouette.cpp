#include "reconstruct/Silhouette.h"

namespace nprgl::reconstruct {

namespace {

inline float facing(const Mesh::Normal& n, const glm::vec3& view)
{
    return n[0] * view.x + n[1] * view.y + n[2] * view.z;
}

inline bool silhouette(const EdgeInfo& e, const Mesh::Point* points,
                       const Mesh::Normal* faceNormals, const glm::vec3& eye)
{
    const Mesh::Point& a = points[e.v0];
    const Mesh::Point& b = points[e.v1];
    const glm::vec3 view = eye - 0.5f * glm::vec3(a[0] + b[0], a[1] + b[1], a[2] + b[2]);
    if (e.f0 == kNoIndex || e.f1 == kNoIndex)
        return facing(faceNormals[e.f0 != kNoIndex ? e.f0 : e.f1], view) > 0.0f;
    // Signs compared, not the product, which can underflow to 0.
    const float d0 = facing(faceNormals[e.f0], view);
    const float d1 = facing(faceNormals[e.f1], view);
    return (d0 < 0.0f && d1 > 0.0f) || (d0 > 0.0f && d1 < 0.0f);
}

const Mesh::Normal* faceNormals(const ObjectMesh& object)
{
    return object.mesh.property(object.mesh.face_normals_pph()).data();
}

} // namespace

glm::vec3 eyeInObjectSpace(const glm::mat4& modelview) noexcept
{
    const glm::vec4 eye = glm::inverse(modelview) * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f);
    return eye.w != 0.0f ? glm::vec3(eye) / eye.w : glm::vec3(eye);
}

bool isSilhouette(const ObjectMesh& object, EdgeIndex edge, const glm::vec3& eye) noexcept
{
    if (edge >= object.edges.size()) return false;
    return silhouette(object.edges[edge], object.mesh.points(), faceNormals(object), eye);
}

void silhouetteEdges(const ObjectMesh& object, const glm::vec3& eye,
                     std::vector<EdgeIndex>& out) noexcept
{
    out.clear();
    const Mesh::Point* points = object.mesh.points();
    const Mesh::Normal* normals = faceNormals(object);
    const uint32_t count = uint32_t(object.edges.size());
    try {
        for (uint32_t e = 0; e < count; ++e) {
            if (silhouette(object.edges[e], points, normals, eye)) out.push_back(e);
        }
    } catch (...) {
        out.clear(); // out of memory
    }
}

std::vector<EdgeIndex> silhouetteEdges(const ObjectMesh& object, const glm::vec3& eye) noexcept
{
    std::vector<EdgeIndex> out;
    silhouetteEdges(object, eye, out);
    return out;
}

} // namespace nprgl::reconstruct
