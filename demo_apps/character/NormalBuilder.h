#pragma once

#include "CharacterPose.h"

#include <cstdint>
#include <vector>

namespace character {

// Smooth vertex normals from the area-weighted normals of the triangles around each vertex.
void buildNormals(std::vector<Vertex>& vertices, const std::vector<uint32_t>& indices);

} // namespace character
