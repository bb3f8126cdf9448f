#pragma once

#include "reconstruct/ObjectMesh.h"
#include "styles/strokes/StrokeTypes.h"

#include <glm/glm.hpp>

namespace nprgl::styles::strokes {

// Projects edge chains to window coordinates (thesis §4.4.4 works on screen segments). Each
// point also gets a depth moved towards the eye by `depthTolerance` (a fraction of its eye
// distance), the band within which a surface at the same place does not hide the line.
// Segments with an end at or behind the eye plane are marked hidden; all others unknown.
class ChainProjector {
public:
    void project(const reconstruct::ObjectMesh& mesh, const EdgeChains& chains,
                 const glm::mat4& modelview, const glm::mat4& projection,
                 const glm::ivec4& viewport, float depthTolerance, Polylines& out) const;
};

} // namespace nprgl::styles::strokes
