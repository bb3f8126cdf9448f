#include "reconstruct/MeshGeometry.h"

#include <cmath>

namespace nprgl::reconstruct {

namespace {

inline glm::vec3 toGlm(const Mesh::Point& p)
{
    return {p[0], p[1], p[2]};
}

inline glm::vec3 normalizedOrZero(const glm::vec3& v)
{
    const float len2 = glm::dot(v, v);
    return len2 > 0.0f && std::isfinite(len2) ? v * (1.0f / std::sqrt(len2)) : glm::vec3(0.0f);
}

// Area-weighted normal from the faces around v, for the rare vertex whose given normals
// cancel out when no per-vertex area sums were accumulated.
glm::vec3 areaNormal(const ObjectMesh& object, uint32_t v)
{
    const Mesh& mesh = object.mesh;
    glm::vec3 sum(0.0f);
    for (const OpenMesh::FaceHandle fh : mesh.vf_range(OpenMesh::VertexHandle(int(v)))) {
        const uint32_t* fv = &object.faceVertices[3 * size_t(fh.idx())];
        const glm::vec3 p0 = toGlm(mesh.point(OpenMesh::VertexHandle(int(fv[0]))));
        sum += glm::cross(toGlm(mesh.point(OpenMesh::VertexHandle(int(fv[1])))) - p0,
                          toGlm(mesh.point(OpenMesh::VertexHandle(int(fv[2])))) - p0);
    }
    return normalizedOrZero(sum);
}

} // namespace

void GeometryScratch::prepare(size_t vertexCount)
{
    points.resize(vertexCount);
    givenSum.assign(vertexCount, glm::vec3(0.0f));
    missingNormals = 0;
}

void GeometryScratch::addSplitVertices(const ObjectMesh::UpdateState& state,
                                       const Vertex* sources)
{
    for (const uint32_t v : state.splitVertices) {
        const Vertex& source = sources[state.vertexSource[v]];
        points[v] = Mesh::Point(source.position.x, source.position.y, source.position.z);
        if (source.hasNormal) givenSum[v] = source.normal;
        else ++missingNormals;
    }
}

void gatherSources(const ObjectMesh& object, GeometryScratch& scratch)
{
    const ObjectMesh::UpdateState& state = object.updateState;
    scratch.prepare(object.mesh.n_vertices());
    const Vertex* sources = object.sourceVertices.data();
    const uint32_t count = uint32_t(object.sourceVertices.size());
    for (uint32_t i = 0; i < count; ++i) {
        const uint32_t w = state.weld[i];
        if (w != kNoIndex) scratch.add(state, sources[i], i, w);
    }
    scratch.addSplitVertices(state, sources);
}

void computeGeometry(ObjectMesh& object, float creaseCosine, GeometryScratch& scratch)
{
    // Raw property arrays: per-element property lookups cost more than the arithmetic.
    Mesh& mesh = object.mesh;
    std::vector<Mesh::Point>& points = mesh.property(mesh.points_pph()).data_vector();
    std::vector<Mesh::Normal>& vertexNormals =
        mesh.property(mesh.vertex_normals_pph()).data_vector();
    std::vector<Mesh::Normal>& faceNormals = mesh.property(mesh.face_normals_pph()).data_vector();
    points.swap(scratch.points);
    const size_t vertexCount = points.size();
    const size_t faceCount = faceNormals.size();

    // Area-weighted sums only where some vertex has no normal from the program (lit programs
    // give them all): three scattered additions per face saved.
    const bool areaNeeded = scratch.missingNormals > 0;
    scratch.areaSum.assign(areaNeeded ? vertexCount : 0, glm::vec3(0.0f));
    glm::vec3* areaSum = scratch.areaSum.data();
    const uint32_t* faceVertices = object.faceVertices.data();
    for (size_t f = 0; f < faceCount; ++f) {
        const uint32_t* fv = faceVertices + 3 * f;
        const glm::vec3 p0 = toGlm(points[fv[0]]);
        // |cross| is twice the area: summing it weights vertex normals by area.
        const glm::vec3 c = glm::cross(toGlm(points[fv[1]]) - p0, toGlm(points[fv[2]]) - p0);
        const glm::vec3 n = normalizedOrZero(c);
        faceNormals[f] = Mesh::Normal(n.x, n.y, n.z);
        if (areaNeeded) {
            areaSum[fv[0]] += c;
            areaSum[fv[1]] += c;
            areaSum[fv[2]] += c;
        }
    }
    const glm::vec3* givenSum = scratch.givenSum.data();
    for (size_t v = 0; v < vertexCount; ++v) {
        // The program's normals where it gave any (and they do not cancel out).
        glm::vec3 n = normalizedOrZero(givenSum[v]);
        if (n == glm::vec3(0.0f))
            n = areaNeeded ? normalizedOrZero(areaSum[v]) : areaNormal(object, uint32_t(v));
        vertexNormals[v] = Mesh::Normal(n.x, n.y, n.z);
    }

    const uint32_t* materials = object.faceMaterials.data();
    const EdgeInfo* edges = object.edges.data();
    uint8_t* classes = object.edgeClasses.data();
    const size_t edgeCount = object.edges.size();
    for (size_t e = 0; e < edgeCount; ++e) {
        if (classes[e] & kEdgeBorder) continue;
        const uint32_t f0 = edges[e].f0, f1 = edges[e].f1;
        const Mesh::Normal& n0 = faceNormals[f0];
        const Mesh::Normal& n1 = faceNormals[f1];
        const float d = n0[0] * n1[0] + n0[1] * n1[1] + n0[2] * n1[2];
        // A zero normal (degenerate face) says nothing about the dihedral angle.
        const bool valid = n0.sqrnorm() > 0.0f && n1.sqrnorm() > 0.0f;
        uint8_t c = 0;
        if (valid && d < creaseCosine) c |= kEdgeCrease;
        if (materials[f0] != materials[f1]) c |= kEdgeMaterial;
        classes[e] = c;
    }
}

} // namespace nprgl::reconstruct
