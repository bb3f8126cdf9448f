#include "styles/outlines/EdgeView.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace nprgl::styles {

EdgeView::EdgeView(const SceneObject& object)
    : mMesh(*object.mesh),
      mNormalMatrix(glm::inverseTranspose(glm::mat3(object.modelview))),
      mOrthographic(object.orthographic())
{
}

bool EdgeView::facesEye(uint32_t face, const glm::vec3& eyePoint) const
{
    const glm::vec3 n = mNormalMatrix * mMesh.faceNormal(face);
    return glm::dot(n, mOrthographic ? glm::vec3(0, 0, 1) : -eyePoint) > 0.0f;
}

bool EdgeView::silhouette(const reconstruct::EdgeInfo& edge, const glm::vec3& eyeMid) const
{
    if (edge.f0 == reconstruct::kNoIndex || edge.f1 == reconstruct::kNoIndex) return false;
    return facesEye(edge.f0, eyeMid) != facesEye(edge.f1, eyeMid);
}

bool EdgeView::feature(size_t e) const
{
    const uint8_t c = e < mMesh.edgeClasses.size() ? mMesh.edgeClasses[e] : 0;
    return (c & (reconstruct::kEdgeBorder | reconstruct::kEdgeCrease)) != 0;
}

} // namespace nprgl::styles
