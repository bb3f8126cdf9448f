#pragma once

#include "reconstruct/ObjectMesh.h"
#include "styles/GlFunctions.h"

#include <cstdint>
#include <memory>
#include <unordered_map>

namespace nprgl::styles {

// GPU copies of the scene's meshes, one vertex per face corner (3 per face, in face order):
// attribute 0 position (the program's, object space), 1 normal (the program's at that
// corner, else the welded vertex normal), 2 colour, 3 texcoord, 4 the face's geometric
// normal (cross(p1 - p0, p2 - p0), unnormalised, object space). Kept while a mesh with that
// content and geometry version is drawn; dropped when unused for a few flushes.
class MeshBuffers {
public:
    // Binds the mesh's corner buffer and points attributes 0-4 at it (the caller's VAO is
    // bound). Returns the number of vertices to draw as GL_TRIANGLES.
    GLsizei bind(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh);
    // Draws the mesh's triangles with the current program.
    void draw(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh);
    // Called once per flush: forgets buffers unused for a while.
    void endFlush(const GlFunctions& gl);
    void destroy(const GlFunctions& gl);

private:
    struct Entry {
        GLuint buffer = 0;
        GLsizei vertices = 0;
        uint64_t contentKey = 0;
        uint32_t geometryVersion = 0;
        uint64_t lastUsed = 0;
    };
    std::unordered_map<const reconstruct::ObjectMesh*, Entry> mEntries;
    uint64_t mFlush = 0;
};

} // namespace nprgl::styles
