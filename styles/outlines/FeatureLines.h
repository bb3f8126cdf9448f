// FeatureLines: the mesh edges along which an image-space edge can lie, for the edge operator.
#pragma once

#include "reconstruct/ObjectMesh.h"

#include <cstdint>
#include <vector>

namespace nprgl::styles {

// The image-space operator marks a pixel where it differs from a neighbour in depth, normal,
// colour or object. Within one triangle all of these vary smoothly, and across an edge
// shared by two coplanar faces that agree in their corners' normals and colours nothing
// changes either, so every line it can find (but where surfaces cut through each other or
// through a clip plane) lies along the other edges: borders, folds, and edges where the
// corners' attributes or the faces' materials differ. Running the operator only on pixels
// near those edges gives the full-window pass's lines for a fraction of its fragments.
class FeatureLines {
public:
    // Appends the feature edges of `mesh` as pairs of corners (indices into its source
    // vertices, as MeshBuffers uploads them), for GL_LINES.
    static void collect(const reconstruct::ObjectMesh& mesh, std::vector<uint32_t>& pairs);
};

} // namespace nprgl::styles
