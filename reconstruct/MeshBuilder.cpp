#include "reconstruct/MeshBuilder.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "reconstruct/PrimitiveAssembly.h"

namespace nprgl::reconstruct {

namespace {

using OpenMesh::HalfedgeHandle;
using OpenMesh::VertexHandle;

// How many of a vertex's split copies a refused face tries before making a new one; bounds
// the cost of pathological input (hundreds of faces stacked on one spot).
constexpr size_t kCopiesTried = 8;

inline bool isFinite(const glm::vec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Collinear within float precision: sin of the corner angle below 1e-6, computed in double so
// that small triangles far from the origin are judged by their shape, not by rounding.
inline bool zeroArea(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c)
{
    const glm::dvec3 e1 = glm::dvec3(b) - glm::dvec3(a);
    const glm::dvec3 e2 = glm::dvec3(c) - glm::dvec3(a);
    const glm::dvec3 x = glm::cross(e1, e2);
    return glm::dot(x, x) <= 1e-12 * glm::dot(e1, e1) * glm::dot(e2, e2);
}

// The checks of OpenMesh's PolyConnectivity::add_face (complex vertex, complex edge, patch
// re-linking), read-only: a face it would refuse is never offered to it, which would also
// print to stderr. Returns a bit per corner at fault, 0 when add_face will succeed.
unsigned refusedCorners(const Mesh& mesh, const VertexHandle vh[3])
{
    unsigned bad = 0;
    HalfedgeHandle heh[3];
    for (int i = 0; i < 3; ++i) {
        const int next = (i + 1) % 3;
        if (!mesh.is_boundary(vh[i])) bad |= 1u << i;
        heh[i] = mesh.find_halfedge(vh[i], vh[next]);
        if (heh[i].is_valid() && !mesh.is_boundary(heh[i])) bad |= (1u << i) | (1u << next);
    }
    if (bad) return bad;
    for (int i = 0; i < 3; ++i) {
        const int next = (i + 1) % 3;
        const HalfedgeHandle innerPrev = heh[i], innerNext = heh[next];
        if (!innerPrev.is_valid() || !innerNext.is_valid()) continue;
        if (mesh.next_halfedge_handle(innerPrev) == innerNext) continue;
        // OpenMesh looks for another boundary gap at this vertex to move the patch into.
        HalfedgeHandle boundaryPrev = mesh.opposite_halfedge_handle(innerNext);
        do {
            boundaryPrev = mesh.opposite_halfedge_handle(mesh.next_halfedge_handle(boundaryPrev));
        } while (!mesh.is_boundary(boundaryPrev));
        if (boundaryPrev == innerPrev) bad |= 1u << next;
    }
    return bad;
}

uint32_t totalVertices(const Batch* batches, size_t count)
{
    size_t total = 0;
    for (size_t b = 0; b < count; ++b) total += batches[b].vertices.size();
    return uint32_t(total);
}

void fillMaterials(ObjectMesh& object, const Batch* batches, size_t count)
{
    const std::vector<uint32_t>& faceEnd = object.updateState.batchFaceEnd;
    uint32_t begin = 0;
    for (size_t b = 0; b < count; ++b) {
        std::fill(object.faceMaterials.begin() + begin, object.faceMaterials.begin() + faceEnd[b],
                  batches[b].materialId);
        begin = faceEnd[b];
    }
}

} // namespace

VertexHandle MeshBuilder::vertexFor(ObjectMesh& object, uint32_t welded)
{
    uint32_t& v = mMeshVertex[welded];
    if (v == kNoIndex) {
        // Points are written by computeGeometry; connectivity does not look at them.
        v = uint32_t(object.mesh.new_vertex().idx());
        object.updateState.vertexSource.push_back(object.updateState.weldRep[welded]);
    }
    return VertexHandle(int(v));
}

VertexHandle MeshBuilder::copyOf(ObjectMesh& object, uint32_t welded)
{
    const VertexHandle vh = object.mesh.new_vertex();
    object.updateState.vertexSource.push_back(object.updateState.weldRep[welded]);
    mCopies[welded].push_back(uint32_t(vh.idx()));
    ++object.stats.splitVertices;
    return vh;
}

// A face OpenMesh refuses (an edge's third face, a flipped neighbour, a duplicate) goes onto
// copies of its faulty corners: first copies made for earlier refused faces, so a whole second
// sheet glued along a non-manifold edge stays connected to itself, then new ones, and at worst
// three new vertices, which always works. The face is never dropped.
void MeshBuilder::splitFace(ObjectMesh& object, VertexHandle vh[3])
{
    const Mesh& mesh = object.mesh;
    const ObjectMesh::UpdateState& state = object.updateState;
    uint32_t welded[3];
    for (int k = 0; k < 3; ++k) welded[k] = state.weld[state.vertexSource[vh[k].idx()]];
    ++object.stats.splitFaces;
    unsigned bad = refusedCorners(mesh, vh);
    for (int k = 0; k < 3; ++k) {
        if (!(bad & (1u << k))) continue;
        VertexHandle pick;
        const auto it = mCopies.find(welded[k]);
        if (it != mCopies.end()) {
            const std::vector<uint32_t>& copies = it->second;
            for (size_t j = copies.size(), tried = 0; j-- > 0 && tried < kCopiesTried; ++tried) {
                const VertexHandle candidate(int(copies[j]));
                if (candidate != vh[k] && mesh.is_boundary(candidate)) {
                    pick = candidate;
                    break;
                }
            }
        }
        vh[k] = pick.is_valid() ? pick : copyOf(object, welded[k]);
    }
    bad = refusedCorners(mesh, vh);
    for (int k = 0; k < 3; ++k) {
        if (bad & (1u << k)) vh[k] = copyOf(object, welded[k]);
    }
    if (refusedCorners(mesh, vh) != 0) {
        for (int k = 0; k < 3; ++k) vh[k] = copyOf(object, welded[k]);
    }
}

void MeshBuilder::addFace(ObjectMesh& object, uint32_t f, VertexHandle vh[3])
{
    Mesh& mesh = object.mesh;
    if (refusedCorners(mesh, vh) != 0) splitFace(object, vh);
    if (!mesh.add_face(vh[0], vh[1], vh[2]).is_valid()) {
        // Not expected (refusedCorners mirrors add_face), but never lose the face.
        const ObjectMesh::UpdateState& state = object.updateState;
        for (int k = 0; k < 3; ++k)
            vh[k] = copyOf(object, state.weld[state.vertexSource[vh[k].idx()]]);
        mesh.add_face(vh[0], vh[1], vh[2]);
    }
    for (int k = 0; k < 3; ++k) object.faceVertices[3 * size_t(f) + k] = uint32_t(vh[k].idx());
}

// OpenMesh accepts a bow-tie (two fans of faces meeting at one vertex) but circulating such a
// vertex, its normal and stroke chaining through it are ill-defined. Each fan after the first
// (the one with the earliest face) gets its own copy of the vertex. Returns true when faces
// moved; the caller then rebuilds the connectivity.
bool MeshBuilder::splitFans(ObjectMesh& object)
{
    const Mesh& mesh = object.mesh;
    const uint32_t vertexCount = uint32_t(mesh.n_vertices());
    const uint32_t halfedgeCount = uint32_t(mesh.n_halfedges());
    // One outgoing boundary halfedge per gap between fans: two or more means a bow-tie.
    mBoundaryOut.assign(vertexCount, 0);
    bool any = false;
    for (uint32_t h = 0; h < halfedgeCount; ++h) {
        const OpenMesh::HalfedgeHandle heh{int(h)};
        if (mesh.face_handle(heh).is_valid()) continue;
        uint8_t& n = mBoundaryOut[mesh.from_vertex_handle(heh).idx()];
        if (n < 2 && ++n == 2) any = true;
    }
    if (!any) return false;

    bool moved = false;
    ObjectMesh::UpdateState& state = object.updateState;
    std::vector<uint32_t> faces, parent, copyOfRoot;
    for (uint32_t v = 0; v < vertexCount; ++v) {
        if (mBoundaryOut[v] < 2) continue;
        const VertexHandle vh{int(v)};
        faces.clear();
        for (const OpenMesh::HalfedgeHandle heh : mesh.voh_range(vh)) {
            const OpenMesh::FaceHandle fh = mesh.face_handle(heh);
            if (fh.is_valid()) faces.push_back(uint32_t(fh.idx()));
        }
        std::sort(faces.begin(), faces.end());
        // Union-find over the faces around v (sorted, so a set's root is its earliest face):
        // faces that share an edge at v are one fan.
        parent.resize(faces.size());
        for (size_t i = 0; i < parent.size(); ++i) parent[i] = uint32_t(i);
        auto local = [&](OpenMesh::FaceHandle fh) {
            return uint32_t(std::lower_bound(faces.begin(), faces.end(), uint32_t(fh.idx())) -
                            faces.begin());
        };
        auto root = [&](uint32_t i) {
            while (parent[i] != i) i = parent[i] = parent[parent[i]];
            return i;
        };
        for (const OpenMesh::HalfedgeHandle heh : mesh.voh_range(vh)) {
            const OpenMesh::FaceHandle a = mesh.face_handle(heh);
            const OpenMesh::FaceHandle b = mesh.opposite_face_handle(heh);
            if (!a.is_valid() || !b.is_valid()) continue;
            const uint32_t ra = root(local(a)), rb = root(local(b));
            if (ra != rb) parent[std::max(ra, rb)] = std::min(ra, rb);
        }
        // Fan 0 (with the earliest face) keeps v; every other fan gets a copy.
        copyOfRoot.assign(faces.size(), kNoIndex);
        for (uint32_t i = 0; i < faces.size(); ++i) {
            const uint32_t r = root(i);
            if (r == 0) continue;
            if (copyOfRoot[r] == kNoIndex) {
                copyOfRoot[r] = uint32_t(state.vertexSource.size());
                state.vertexSource.push_back(state.vertexSource[v]);
                ++object.stats.splitVertices;
            }
            uint32_t* fv = &object.faceVertices[3 * size_t(faces[i])];
            for (int k = 0; k < 3; ++k) {
                if (fv[k] == v) fv[k] = copyOfRoot[r];
            }
            ++object.stats.splitFaces;
            moved = true;
        }
    }
    return moved;
}

void MeshBuilder::buildEdges(ObjectMesh& object)
{
    const Mesh& mesh = object.mesh;
    const uint32_t edgeCount = uint32_t(mesh.n_edges());
    const uint32_t vertexCount = uint32_t(mesh.n_vertices());
    object.edges.resize(edgeCount);
    std::vector<uint32_t>& start = object.vertexEdgeStart;
    start.assign(vertexCount + 1, 0);
    for (uint32_t e = 0; e < edgeCount; ++e) {
        const HalfedgeHandle h0(int(2 * e)), h1(int(2 * e + 1));
        EdgeInfo& info = object.edges[e];
        info.v0 = uint32_t(mesh.to_vertex_handle(h1).idx());
        info.v1 = uint32_t(mesh.to_vertex_handle(h0).idx());
        const OpenMesh::FaceHandle fh0 = mesh.face_handle(h0), fh1 = mesh.face_handle(h1);
        info.f0 = fh0.is_valid() ? uint32_t(fh0.idx()) : kNoIndex;
        info.f1 = fh1.is_valid() ? uint32_t(fh1.idx()) : kNoIndex;
        info.classes = (fh0.is_valid() && fh1.is_valid()) ? 0 : kEdgeBorder;
        ++start[info.v0 + 1];
        ++start[info.v1 + 1];
    }
    for (uint32_t v = 0; v < vertexCount; ++v) start[v + 1] += start[v];
    object.vertexEdges.resize(start[vertexCount]);
    std::vector<uint32_t> cursor(start.begin(), start.end() - 1);
    for (uint32_t e = 0; e < edgeCount; ++e) {
        object.vertexEdges[cursor[object.edges[e].v0]++] = e;
        object.vertexEdges[cursor[object.edges[e].v1]++] = e;
    }
}

std::shared_ptr<ObjectMesh> MeshBuilder::build(const Batch* batches, size_t count,
                                               const ReconstructParams& params)
{
    auto result = std::make_shared<ObjectMesh>();
    ObjectMesh& object = *result;
    ObjectMesh::UpdateState& state = object.updateState;
    BuildStats& stats = object.stats;

    const uint32_t total = totalVertices(batches, count);
    object.sourceVertices.reserve(total);
    state.batchModes.reserve(count);
    state.batchCounts.reserve(count);
    for (size_t b = 0; b < count; ++b) {
        const std::vector<Vertex>& vertices = batches[b].vertices;
        object.sourceVertices.insert(object.sourceVertices.end(), vertices.begin(),
                                     vertices.end());
        state.batchModes.push_back(batches[b].mode);
        state.batchCounts.push_back(uint32_t(vertices.size()));
    }
    stats.batches = uint32_t(count);
    stats.sourceVertices = total;
    const Vertex* sources = object.sourceVertices.data();

    glm::vec3 lo(FLT_MAX), hi(-FLT_MAX);
    for (uint32_t i = 0; i < total; ++i) {
        const glm::vec3& p = sources[i].position;
        if (!isFinite(p)) continue;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const float diagonal = lo.x <= hi.x ? glm::length(hi - lo) : 0.0f;
    const float tolerance = std::isfinite(diagonal) ? params.weldTolerance * diagonal : 0.0f;
    stats.weldedVertices =
        mWelder.weld(sources, total, lo, hi, tolerance, state.weld, state.weldRep);

    // Assembly: keep the triangles with three finite, distinct, non-collinear corners.
    const uint32_t* weld = state.weld.data();
    mTriangles.clear();
    state.batchFaceEnd.reserve(count);
    uint32_t base = 0;
    for (size_t b = 0; b < count; ++b) {
        const uint32_t n = state.batchCounts[b];
        stats.incompleteVertices += assembleTriangles(
            batches[b].mode, n, [&](uint32_t a, uint32_t bb, uint32_t c) {
                a += base;
                bb += base;
                c += base;
                ++stats.triangles;
                const uint32_t wa = weld[a], wb = weld[bb], wc = weld[c];
                if (wa == kNoIndex || wb == kNoIndex || wc == kNoIndex) {
                    ++stats.nonFiniteTriangles;
                } else if (wa == wb || wb == wc || wa == wc) {
                    ++stats.degenerateTriangles;
                } else if (zeroArea(sources[a].position, sources[bb].position,
                                    sources[c].position)) {
                    ++stats.degenerateTriangles;
                    state.areaDropped.insert(state.areaDropped.end(), {a, bb, c});
                } else {
                    mTriangles.insert(mTriangles.end(), {a, bb, c});
                }
            });
        state.batchFaceEnd.push_back(uint32_t(mTriangles.size() / 3));
        base += n;
    }
    const uint32_t faceCount = uint32_t(mTriangles.size() / 3);

    // Connectivity. Every kept triangle becomes a face, in drawing order.
    Mesh& mesh = object.mesh;
    mesh.reserve(stats.weldedVertices, faceCount * 3 / 2 + 16, faceCount);
    mMeshVertex.assign(stats.weldedVertices, kNoIndex);
    mCopies.clear();
    state.vertexSource.reserve(stats.weldedVertices);
    object.faceVertices.resize(size_t(faceCount) * 3);
    for (uint32_t f = 0; f < faceCount; ++f) {
        const uint32_t* corners = &mTriangles[3 * size_t(f)];
        VertexHandle vh[3] = {vertexFor(object, weld[corners[0]]),
                              vertexFor(object, weld[corners[1]]),
                              vertexFor(object, weld[corners[2]])};
        addFace(object, f, vh);
    }
    if (splitFans(object)) {
        // Some faces moved to new vertices: connect everything again on the final vertices.
        const uint32_t vertexCount = uint32_t(state.vertexSource.size());
        mesh = Mesh();
        mesh.reserve(vertexCount, faceCount * 3 / 2 + 16, faceCount);
        for (uint32_t v = 0; v < vertexCount; ++v) mesh.new_vertex();
        for (uint32_t f = 0; f < faceCount; ++f) {
            const uint32_t* fv = &object.faceVertices[3 * size_t(f)];
            VertexHandle vh[3] = {VertexHandle(int(fv[0])), VertexHandle(int(fv[1])),
                                  VertexHandle(int(fv[2]))};
            addFace(object, f, vh);
        }
    }
    object.faceCorners.assign(mTriangles.begin(), mTriangles.end());
    object.faceMaterials.resize(faceCount);
    fillMaterials(object, batches, count);
    buildEdges(object);
    computeGeometry(object, params.creaseCosine, mGeometry);
    return result;
}

bool MeshBuilder::prepareUpdate(const ObjectMesh& object, const Batch* batches, size_t count,
                                const ReconstructParams& params)
{
    const ObjectMesh::UpdateState& state = object.updateState;
    if (count != state.batchModes.size()) return false;
    for (size_t b = 0; b < count; ++b) {
        if (batches[b].mode != state.batchModes[b]) return false;
        if (batches[b].vertices.size() != state.batchCounts[b]) return false;
    }
    mStaged.clear();
    mStaged.reserve(object.sourceVertices.size());
    for (size_t b = 0; b < count; ++b)
        mStaged.insert(mStaged.end(), batches[b].vertices.begin(), batches[b].vertices.end());

    const Vertex* staged = mStaged.data();
    const size_t total = mStaged.size();
    const uint32_t* weld = state.weld.data();
    glm::vec3 lo(FLT_MAX), hi(-FLT_MAX);
    for (size_t i = 0; i < total; ++i) {
        const glm::vec3& p = staged[i].position;
        const bool finite = isFinite(p);
        if (finite != (weld[i] != kNoIndex)) return false;
        if (!finite) continue;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const float diagonal = lo.x <= hi.x ? glm::length(hi - lo) : 0.0f;
    const float tolerance = std::isfinite(diagonal) ? params.weldTolerance * diagonal : 0.0f;
    const float tol2 = tolerance * tolerance;
    const uint32_t* rep = state.weldRep.data();
    for (size_t i = 0; i < total; ++i) {
        if (weld[i] == kNoIndex) continue;
        const uint32_t r = rep[weld[i]];
        if (r == i) continue;
        const glm::vec3 d = staged[i].position - staged[r].position;
        if (!(glm::dot(d, d) <= tol2)) return false;
    }
    const std::vector<uint32_t>& dropped = state.areaDropped;
    for (size_t t = 0; t + 2 < dropped.size(); t += 3) {
        if (!zeroArea(staged[dropped[t]].position, staged[dropped[t + 1]].position,
                      staged[dropped[t + 2]].position))
            return false;
    }
    return true;
}

void MeshBuilder::applyUpdate(ObjectMesh& object, const Batch* batches, size_t count,
                              const ReconstructParams& params)
{
    // Allocate before anything changes, so running out of memory leaves the mesh intact.
    mGeometry.areaSum.reserve(object.mesh.n_vertices());
    mGeometry.givenSum.reserve(object.mesh.n_vertices());
    object.sourceVertices.swap(mStaged);
    fillMaterials(object, batches, count);
    ++object.geometryVersion;
    computeGeometry(object, params.creaseCosine, mGeometry);
}

} // namespace nprgl::reconstruct
