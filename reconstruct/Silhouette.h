#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "reconstruct/ObjectMesh.h"

namespace nprgl::reconstruct {

// The eye in object space (the origin of eye space through the inverse modelview): transform
// it once per object instead of every vertex and normal (thesis §4.4.3).
glm::vec3 eyeInObjectSpace(const glm::mat4& modelview) noexcept;

// Thesis eq. 4.1: an interior edge with faces n1, n2 and midpoint m is a silhouette when
// (n1·(e−m)) and (n2·(e−m)) have strictly opposite signs, i.e. one face is front-facing and
// the other back-facing as seen from the eye e. Since m lies in both faces' planes this is
// exactly the per-face orientation test, so the silhouette is the border between front- and
// back-facing regions: on a closed mesh it forms closed loops.
// A border edge counts as a silhouette when its one face is front-facing (n·(e−m) > 0): the
// visible rim of an open surface outlines it; a back-facing rim lies behind the surface.
bool isSilhouette(const ObjectMesh& object, EdgeIndex edge, const glm::vec3& eye) noexcept;

// All silhouette edges for this eye, in edge order. The first form reuses `out`'s storage.
void silhouetteEdges(const ObjectMesh& object, const glm::vec3& eye,
                     std::vector<EdgeIndex>& out) noexcept;
std::vector<EdgeIndex> silhouetteEdges(const ObjectMesh& object, const glm::vec3& eye) noexcept;

} // namespace nprgl::reconstruct
