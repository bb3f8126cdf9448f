#pragma once

#include "reconstruct/ObjectMesh.h"
#include "styles/GlFunctions.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace nprgl::styles {

// GPU line lists of each mesh's feature edges (thesis §4.1.1: borders, creases, material
// edges, from ObjectMesh::edgeClasses), two vertices per edge (EdgeLines::Vertex: the point
// and the unit normals of the edge's two faces, which let a shader judge how steep the faces
// beside the line are). An edge of
// several classes is listed once, in the first of border, crease, material. Rebuilt when the
// mesh's content or geometry version changes (creases move with animation); dropped when
// unused for a few flushes.
class EdgeLines {
public:
    enum Kind { Border = 0, Crease = 1, Material = 2, KindCount = 3 };

    struct Vertex {
        glm::vec3 position;
        glm::vec3 faceNormal0; // object space; a border edge repeats its one face's normal
        glm::vec3 faceNormal1;
    };

    struct Lines {
        GLuint buffer = 0;
        std::array<GLint, KindCount> first{};   // first vertex of each kind
        std::array<GLsizei, KindCount> count{}; // vertices of each kind
        glm::vec3 boundsMin{0.0f}, boundsMax{0.0f}; // object-space box of the mesh's points
    };

    // The mesh's lines, built or refreshed as needed; leaves its buffer bound to
    // GL_ARRAY_BUFFER.
    const Lines& bind(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh);
    void endFlush(const GlFunctions& gl);
    void destroy(const GlFunctions& gl);

private:
    struct Entry {
        Lines lines;
        uint64_t contentKey = 0;
        uint32_t geometryVersion = 0;
        uint64_t lastUsed = 0;
        bool built = false;
    };
    std::unordered_map<const reconstruct::ObjectMesh*, Entry> mEntries;
    std::array<std::vector<Vertex>, KindCount> mScratch; // reused between rebuilds
    std::vector<Vertex> mUpload;
    uint64_t mFlush = 0;
};

} // namespace nprgl::styles
