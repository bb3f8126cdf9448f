#pragma once

#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "reconstruct/ObjectMesh.h"

namespace nprgl::reconstruct {

struct ExportObject {
    std::shared_ptr<const ObjectMesh> mesh;
    // Applied to positions (and, as its inverse transpose, to normals): the object's modelview
    // for eye space, the model part of it for world space. Choosing is the caller's business.
    glm::mat4 transform{1.0f};
};

// Writes the objects to one file, the format chosen by the extension (case-insensitive):
// - .obj: written here, one group "g object_N" per object (N = index in `objects`), vertices,
//   per-corner normals (the program's, else the vertex normal) and, when any corner has a
//   non-zero texcoord, per-corner texcoords;
// - .ply, .off: through OpenMesh IO, all objects merged into one mesh with vertex normals
//   (neither format has groups).
// Null meshes are skipped. Returns false with a message in `error`; never throws.
bool exportMeshes(const std::string& path, const std::vector<ExportObject>& objects,
                  std::string& error) noexcept;

} // namespace nprgl::reconstruct
