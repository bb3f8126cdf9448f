#include "styles/MeshBuffers.h"

#include "styles/ObjectNames.h"

#include <algorithm>
#include <vector>

namespace nprgl::styles {

namespace {

using SourceVertex = MeshBuffers::SourceVertexData;

// One vertex per vertex the program sent (strips and fans share theirs), faces as indices:
// a third of the vertex work of one vertex per face corner.
void fill(const reconstruct::ObjectMesh& mesh, std::vector<SourceVertex>& vertices,
          std::vector<uint32_t>& indices)
{
    vertices.resize(mesh.sourceVertices.size());
    for (size_t i = 0; i < mesh.sourceVertices.size(); ++i) {
        const reconstruct::Vertex& c = mesh.sourceVertices[i];
        vertices[i] = {{c.position.x, c.position.y, c.position.z},
                       {c.normal.x, c.normal.y, c.normal.z},
                       {c.color.r, c.color.g, c.color.b, c.color.a},
                       {c.texcoord.x, c.texcoord.y},
                       {c.lightcoord.x, c.lightcoord.y}};
    }
    // Where the program gave no normal, the welded vertex's.
    for (uint32_t f = 0; f < mesh.faceCount(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t source = mesh.faceCorners[3 * f + k];
            if (mesh.sourceVertices[source].hasNormal) continue;
            const glm::vec3 n = mesh.vertexNormal(mesh.faceVertices[3 * f + k]);
            float* out = vertices[source].normal;
            out[0] = n.x;
            out[1] = n.y;
            out[2] = n.z;
        }
    }
    indices.assign(mesh.faceCorners.begin(), mesh.faceCorners.end());
}

} // namespace

GLsizei MeshBuffers::bind(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh)
{
    Entry& e = mEntries[&mesh];
    const bool stale = !e.buffer || e.contentKey != mesh.contentKey ||
                       e.geometryVersion != mesh.geometryVersion;
    if (!e.buffer) {
        ObjectNames::reserve(gl, ObjectNames::Kind::Buffer, 1, &e.buffer);
        ObjectNames::reserve(gl, ObjectNames::Kind::Buffer, 1, &e.indexBuffer);
    }
    gl.BindBuffer(GL_ARRAY_BUFFER, e.buffer);
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, e.indexBuffer); // into the styles' own VAO
    if (stale) {
        fill(mesh, mVertices, mIndices);
        gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(mVertices.size() * sizeof(SourceVertex)),
                      mVertices.data(), GL_STREAM_DRAW);
        gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mIndices.size() * sizeof(uint32_t)),
                      mIndices.data(), GL_STREAM_DRAW);
        e.indices = GLsizei(mIndices.size());
        e.derivedStale = true;
        e.contentKey = mesh.contentKey;
        e.geometryVersion = mesh.geometryVersion;
    }
    e.lastUsed = mFlush;
    const GLsizei stride = sizeof(SourceVertex);
    auto at = [](size_t offset) { return reinterpret_cast<const void*>(offset); };
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, at(offsetof(SourceVertex, position)));
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, at(offsetof(SourceVertex, normal)));
    gl.VertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, stride, at(offsetof(SourceVertex, color)));
    gl.VertexAttribPointer(3, 2, GL_FLOAT, GL_FALSE, stride, at(offsetof(SourceVertex, texcoord)));
    gl.VertexAttribPointer(4, 2, GL_FLOAT, GL_FALSE, stride,
                           at(offsetof(SourceVertex, lightcoord)));
    for (GLuint i = 0; i < 5; ++i) gl.EnableVertexAttribArray(i);
    // Arrays another style left enabled in the shared VAO would be read past their end.
    for (GLuint i = 5; i < 8; ++i) gl.DisableVertexAttribArray(i);
    return e.indices;
}

GLsizei MeshBuffers::bindDerived(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh,
                                 DeriveIndices derive)
{
    if (bind(gl, mesh) <= 0) return 0;
    Entry& e = mEntries[&mesh];
    if (!e.derivedBuffer) {
        ObjectNames::reserve(gl, ObjectNames::Kind::Buffer, 1, &e.derivedBuffer);
    }
    gl.BindBuffer(GL_ELEMENT_ARRAY_BUFFER, e.derivedBuffer); // over the triangles', in the VAO
    if (e.derivedStale) {
        mIndices.clear();
        derive(mesh, mIndices);
        gl.BufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(mIndices.size() * sizeof(uint32_t)),
                      mIndices.data(), GL_STREAM_DRAW);
        e.derivedIndices = GLsizei(mIndices.size());
        e.derivedStale = false;
    }
    return e.derivedIndices;
}

void MeshBuffers::draw(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh)
{
    const GLsizei count = bind(gl, mesh);
    if (count > 0) gl.DrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr);
    // Attribute 4 (lightmap coordinates) is the meshes' alone: styles drawing their own
    // arrays through attributes 0-3 must not read it past their end.
    gl.DisableVertexAttribArray(4);
}

void MeshBuffers::drawFaces(const GlFunctions& gl, const reconstruct::ObjectMesh& mesh,
                            uint32_t firstFace, uint32_t faceCount)
{
    const size_t total = size_t(std::max<GLsizei>(bind(gl, mesh), 0));
    const size_t first = std::min(3 * size_t(firstFace), total);
    const size_t n = std::min(3 * size_t(faceCount), total - first);
    if (n > 0) {
        gl.DrawElements(GL_TRIANGLES, GLsizei(n), GL_UNSIGNED_INT,
                        reinterpret_cast<const void*>(first * sizeof(uint32_t)));
    }
    gl.DisableVertexAttribArray(4);
}

void MeshBuffers::endFlush(const GlFunctions& gl)
{
    ++mFlush;
    for (auto it = mEntries.begin(); it != mEntries.end();) {
        // A mesh pointer unused for 8 flushes may be freed and its address reused.
        if (mFlush - it->second.lastUsed > 8) {
            gl.DeleteBuffers(1, &it->second.buffer);
            gl.DeleteBuffers(1, &it->second.indexBuffer);
            if (it->second.derivedBuffer) gl.DeleteBuffers(1, &it->second.derivedBuffer);
            it = mEntries.erase(it);
        } else {
            ++it;
        }
    }
}

void MeshBuffers::destroy(const GlFunctions& gl)
{
    for (auto& [mesh, e] : mEntries) {
        gl.DeleteBuffers(1, &e.buffer);
        gl.DeleteBuffers(1, &e.indexBuffer);
        if (e.derivedBuffer) gl.DeleteBuffers(1, &e.derivedBuffer);
    }
    mEntries.clear();
}

} // namespace nprgl::styles
