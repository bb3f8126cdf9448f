#pragma once

#include "reconstruct/ObjectMesh.h"
#include "styles/GlFunctions.h"

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

namespace nprgl::styles {

// GPU copies of the scene's meshes: one vertex per vertex the program sent (attribute 0
// position, object space; 1 normal, the program's, else the welded vertex normal; 2 colour;
// 3 texcoord) and the faces as indices into them, in face order. Kept while a mesh with that
// content and geometry version is drawn; dropped when unused for a few flushes.
class MeshBuffers {
public:
    struct SourceVertexData {
        float position[3];
        float normal[3];
        float color[4];
        float texcoord[2];
        float lightcoord[2]; // attribute 4, enabled only while a mesh draws
    };

    // Binds the mesh's vertex and index buffers and points attributes 0-3 at them (the
    // styles' VAO is bound). Returns the number of indices to draw as GL_TRIANGLES.
    GLsizei bind(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh);
    // Fills a second index list over the same vertices (e.g. GL_LINES pairs) from the mesh.
    using DeriveIndices = void (*)(const reconstruct::ObjectMesh&, std::vector<uint32_t>&);
    // Binds the mesh's vertices (as bind()) and its index list made by `derive`, remade when
    // the mesh changes. Returns the number of indices in it. One derivation per mesh.
    GLsizei bindDerived(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh,
                        DeriveIndices derive);
    // Draws the mesh's triangles with the current program.
    void draw(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh);
    // Draws faces [firstFace, firstFace + faceCount) of the mesh.
    void drawFaces(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh, uint32_t firstFace,
                   uint32_t faceCount);
    // Called once per flush: forgets buffers unused for a while.
    void endFlush(const GlFunctions& gl);
    void destroy(const GlFunctions& gl);

private:
    struct Entry {
        GLuint buffer = 0;
        GLuint indexBuffer = 0;
        GLsizei indices = 0;
        GLuint derivedBuffer = 0; // bindDerived's
        GLsizei derivedIndices = 0;
        bool derivedStale = true;
        uint64_t contentKey = 0;
        uint32_t geometryVersion = 0;
        uint64_t lastUsed = 0;
    };
    std::unordered_map<const reconstruct::ObjectMesh*, Entry> mEntries;
    uint64_t mFlush = 0;
    std::vector<SourceVertexData> mVertices; // reused upload staging
    std::vector<uint32_t> mIndices;
};

} // namespace nprgl::styles
