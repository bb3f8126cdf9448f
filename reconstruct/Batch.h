#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace nprgl::reconstruct {

// One vertex as the GL received it.
struct Vertex {
    glm::vec3 position;       // object space (already divided by w if w != 1)
    glm::vec3 normal;         // the current normal at that vertex
    glm::vec4 color;          // current colour, or the material's diffuse when lighting
    glm::vec2 texcoord;       // the surface's texture unit
    glm::vec2 lightcoord;     // the lightmap's unit (a layer modulating the surface), if any
    bool hasNormal = false;   // the program ever set a normal for this batch
    uint8_t padding[3] = {};  // explicit and zero, so a vertex array hashes deterministically
};
static_assert(sizeof(Vertex) == 60, "Vertex must have no hidden padding");

// Which diagonal cuts each quad of GL_QUADS into two triangles. GL leaves it to the
// implementation; Mesa (22.x, llvmpipe) cuts glBegin/glEnd and glDrawArrays quads along v0-v2
// and indexed ones (glDrawElements, and display lists, which it compiles into indexed draws)
// along v1-v3. It shows wherever a quad's corners differ in colour or are not coplanar.
enum class QuadCut : uint8_t { V0V2, V1V3 };

// One glBegin/glEnd or one draw call.
struct Batch {
    uint32_t mode = 0;          // GL_TRIANGLES, GL_TRIANGLE_STRIP, GL_TRIANGLE_FAN, GL_QUADS,
                                // GL_QUAD_STRIP, GL_POLYGON; other modes assemble no triangle
    std::vector<Vertex> vertices;
    glm::mat4 modelview{1.0f};  // at the draw
    uint32_t materialId = 0;    // distinct material/colour state -> distinct id
    uint32_t pass = 0;          // batches of different passes (opaque, translucent) never
                                // form one object
    // Drawn under glFrontFace(GL_CW): its triangles are assembled the other way round, so
    // that an object's front faces are counter-clockwise whichever way each batch was wound.
    bool clockwise = false;
    QuadCut quadCut = QuadCut::V0V2;
    uint64_t contentHash = 0;   // hashBatch(*this); 0 means "not given", the Reconstructor
                                // then computes it (a cost per frame for large batches)
};

// The mode with the winding and the quad cut the batch is assembled with: what its triangles
// depend on.
inline uint32_t assemblyMode(uint32_t mode, bool clockwise, QuadCut cut)
{
    return mode | (clockwise ? 0x80000000u : 0u) | (cut == QuadCut::V1V3 ? 0x40000000u : 0u);
}
inline uint32_t assemblyMode(const Batch& batch)
{
    return assemblyMode(batch.mode, batch.clockwise, batch.quadCut);
}

// XXH3 of the vertex bytes seeded with the assembly mode; never 0. The producer should store it in
// Batch::contentHash when it copies the vertices, while they are hot in the cache.
uint64_t hashBatch(const Batch& batch) noexcept;
// The same for vertices not (yet) in a Batch; `mode` is their assemblyMode.
uint64_t hashVertices(const Vertex* vertices, size_t count, uint32_t mode) noexcept;

} // namespace nprgl::reconstruct
