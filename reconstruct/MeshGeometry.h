#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "reconstruct/ObjectMesh.h"

namespace nprgl::reconstruct {

// Everything that follows from positions, corner attributes and materials once connectivity
// is fixed: points (from updateState.vertexSource), face normals, vertex normals, crease and
// material bits of the edges. Shared by a full build and an in-place update. The scratch
// vectors are reused between calls.
struct GeometryScratch {
    std::vector<glm::vec3> areaSum;
    std::vector<glm::vec3> givenSum;
};

void computeGeometry(ObjectMesh& object, float creaseCosine, GeometryScratch& scratch);

} // namespace nprgl::reconstruct
