#include "styles/MeshBuffers.h"

#include <vector>

namespace nprgl::styles {

namespace {

struct CornerVertex {
    float position[3];
    float normal[3];
    float color[4];
    float texcoord[2];
    float faceNormal[3];
};

void fill(const reconstruct::ObjectMesh& mesh, std::vector<CornerVertex>& out)
{
    out.resize(size_t(mesh.faceCount()) * 3);
    for (uint32_t f = 0; f < mesh.faceCount(); ++f) {
        const glm::vec3 p0 = mesh.corner(f, 0).position;
        const glm::vec3 face =
            glm::cross(mesh.corner(f, 1).position - p0, mesh.corner(f, 2).position - p0);
        for (int k = 0; k < 3; ++k) {
            const reconstruct::Vertex& c = mesh.corner(f, k);
            const glm::vec3 n =
                c.hasNormal ? c.normal : mesh.vertexNormal(mesh.faceVertices[3 * f + k]);
            CornerVertex& v = out[3 * size_t(f) + k];
            v = {{c.position.x, c.position.y, c.position.z},
                 {n.x, n.y, n.z},
                 {c.color.r, c.color.g, c.color.b, c.color.a},
                 {c.texcoord.x, c.texcoord.y},
                 {face.x, face.y, face.z}};
        }
    }
}

} // namespace

GLsizei MeshBuffers::bind(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh)
{
    Entry& e = mEntries[&mesh];
    const bool stale = !e.buffer || e.contentKey != mesh.contentKey ||
                       e.geometryVersion != mesh.geometryVersion;
    if (!e.buffer) gl.GenBuffers(1, &e.buffer);
    gl.BindBuffer(GL_ARRAY_BUFFER, e.buffer);
    if (stale) {
        std::vector<CornerVertex> corners;
        fill(mesh, corners);
        gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(corners.size() * sizeof(CornerVertex)),
                      corners.data(), GL_STREAM_DRAW);
        e.vertices = GLsizei(corners.size());
        e.contentKey = mesh.contentKey;
        e.geometryVersion = mesh.geometryVersion;
    }
    e.lastUsed = mFlush;
    const GLsizei stride = sizeof(CornerVertex);
    auto at = [](size_t offset) { return reinterpret_cast<const void*>(offset); };
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, at(offsetof(CornerVertex, position)));
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, at(offsetof(CornerVertex, normal)));
    gl.VertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, at(offsetof(CornerVertex, color)));
    gl.VertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, stride, at(offsetof(CornerVertex, texcoord)));
    gl.VertexAttribPointer(4, 3, GL_FLOAT, GL_FALSE, stride,
                           at(offsetof(CornerVertex, faceNormal)));
    for (GLuint i = 0; i < 5; ++i) gl.EnableVertexAttribArray(i);
    return e.vertices;
}

void MeshBuffers::draw(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh)
{
    const GLsizei count = bind(gl, mesh);
    if (count > 0) gl.DrawArrays(GL_TRIANGLES, 0, count);
}

void MeshBuffers::endFlush(const GlFunctions& gl)
{
    ++mFlush;
    for (auto it = mEntries.begin(); it != mEntries.end();) {
        // A mesh pointer unused for 8 flushes may be freed and its address reused.
        if (mFlush - it->second.lastUsed > 8) {
            gl.DeleteBuffers(1, &it->second.buffer);
            it = mEntries.erase(it);
        } else {
            ++it;
        }
    }
}

void MeshBuffers::destroy(const GlFunctions& gl)
{
    for (auto& [mesh, e] : mEntries) gl.DeleteBuffers(1, &e.buffer);
    mEntries.clear();
}

} // namespace nprgl::styles
