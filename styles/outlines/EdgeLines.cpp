#include "styles/outlines/EdgeLines.h"

#include "styles/ObjectNames.h"

namespace nprgl::styles {

const EdgeLines::Lines& EdgeLines::bind(const GlFunctions& gl,
                                        const reconstruct::ObjectMesh& mesh)
{
    Entry& e = mEntries[&mesh];
    const bool stale = !e.built || e.contentKey != mesh.contentKey ||
                       e.geometryVersion != mesh.geometryVersion;
    if (!e.lines.buffer) ObjectNames::reserve(gl, ObjectNames::Kind::Buffer, 1, &e.lines.buffer);
    gl.BindBuffer(GL_ARRAY_BUFFER, e.lines.buffer);
    e.lastUsed = mFlush;
    if (!stale) return e.lines;

    for (auto& list : mScratch) list.clear();
    const size_t edges = std::min(mesh.edges.size(), mesh.edgeClasses.size());
    for (size_t i = 0; i < edges; ++i) {
        const uint8_t c = mesh.edgeClasses[i];
        int kind = (c & reconstruct::kEdgeBorder)     ? Border
                   : (c & reconstruct::kEdgeCrease)   ? Crease
                   : (c & reconstruct::kEdgeMaterial) ? Material
                                                      : -1;
        if (kind < 0) continue;
        const reconstruct::EdgeInfo& edge = mesh.edges[i];
        const uint32_t f0 = edge.f0 != reconstruct::kNoIndex ? edge.f0 : edge.f1;
        const uint32_t f1 = edge.f1 != reconstruct::kNoIndex ? edge.f1 : f0;
        const glm::vec3 n0 = f0 != reconstruct::kNoIndex ? mesh.faceNormal(f0) : glm::vec3(0);
        const glm::vec3 n1 = f1 != reconstruct::kNoIndex ? mesh.faceNormal(f1) : n0;
        mScratch[size_t(kind)].push_back({mesh.position(edge.v0), n0, n1});
        mScratch[size_t(kind)].push_back({mesh.position(edge.v1), n0, n1});
    }
    mUpload.clear();
    for (int k = 0; k < KindCount; ++k) {
        e.lines.first[size_t(k)] = GLint(mUpload.size());
        e.lines.count[size_t(k)] = GLsizei(mScratch[size_t(k)].size());
        mUpload.insert(mUpload.end(), mScratch[size_t(k)].begin(), mScratch[size_t(k)].end());
    }
    // Bounds for the depth cue: the points, not only the edge vertices.
    glm::vec3 lo(0.0f), hi(0.0f);
    for (uint32_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec3 p = mesh.position(v);
        lo = v ? glm::min(lo, p) : p;
        hi = v ? glm::max(hi, p) : p;
    }
    e.lines.boundsMin = lo;
    e.lines.boundsMax = hi;
    // An empty list still gets a (tiny) store so the buffer is valid to point at.
    const size_t bytes = std::max<size_t>(mUpload.size(), 1) * sizeof(Vertex);
    gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(bytes), mUpload.empty() ? nullptr : mUpload.data(),
                  GL_STATIC_DRAW);
    e.contentKey = mesh.contentKey;
    e.geometryVersion = mesh.geometryVersion;
    e.built = true;
    return e.lines;
}

void EdgeLines::endFlush(const GlFunctions& gl)
{
    ++mFlush;
    for (auto it = mEntries.begin(); it != mEntries.end();) {
        // Like MeshBuffers: a mesh unused for 8 flushes may be freed and its address reused.
        if (mFlush - it->second.lastUsed > 8) {
            gl.DeleteBuffers(1, &it->second.lines.buffer);
            it = mEntries.erase(it);
        } else {
            ++it;
        }
    }
}

void EdgeLines::destroy(const GlFunctions& gl)
{
    for (auto& [mesh, e] : mEntries) gl.DeleteBuffers(1, &e.lines.buffer);
    mEntries.clear();
}

} // namespace nprgl::styles
