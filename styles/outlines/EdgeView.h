#pragma once

// EdgeView: which of an object's edges a line style draws, as seen from the eye.

#include "reconstruct/ObjectMesh.h"
#include "styles/Scene.h"

#include <glm/glm.hpp>

namespace nprgl::styles {

// The silhouette and feature tests of the line-drawing outlines (depthcue, blueprint), for one
// object in one frame: faces are judged in eye space, towards the eye point (perspective) or
// along the view axis (orthographic).
class EdgeView {
public:
    explicit EdgeView(const SceneObject& object);

    // Whether face f turns its front to the eye at `eyePoint` (a point on it, eye space).
    bool facesEye(uint32_t face, const glm::vec3& eyePoint) const;
    // An edge between two faces of which the eye sees one front and one back.
    bool silhouette(const reconstruct::EdgeInfo& edge, const glm::vec3& eyeMid) const;
    // A border or crease of the mesh (edge index e).
    bool feature(size_t e) const;

private:
    const reconstruct::ObjectMesh& mMesh;
    glm::mat3 mNormalMatrix;
    bool mOrthographic;
};

} // namespace nprgl::styles
