#include "reconstruct/MeshBuilder.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "reconstruct/PrimitiveAssembly.h"

namespace nprgl::reconstruct {

namespace {

using OpenMesh::FaceHandle;
using OpenMesh::HalfedgeHandle;
using OpenMesh::VertexHandle;

// Splitting fans converges in one round; after this many, every face goes on its own.
constexpr int kFanRounds = 3;

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

void fillMaterials(ObjectMesh& object, const Batch* batches, size_t count)
{
    ObjectMesh::UpdateState& state = object.updateState;
    uint32_t begin = 0;
    for (size_t b = 0; b < count; ++b) {
        std::fill(object.faceMaterials.begin() + begin,
                  object.faceMaterials.begin() + state.batchFaceEnd[b], batches[b].materialId);
        begin = state.batchFaceEnd[b];
        state.batchMaterials[b] = batches[b].materialId;
    }
}

} // namespace

uint32_t MeshBuilder::vertexFor(ObjectMesh& object, uint32_t welded)
{
    ObjectMesh::UpdateState& state = object.updateState;
    uint32_t& v = state.weldVertex[welded];
    if (v == kNoIndex) {
        v = uint32_t(state.vertexSource.size());
        state.vertexSource.push_back(state.weldRep[welded]);
    }
    return v;
}

uint32_t MeshBuilder::copyVertex(ObjectMesh& object, uint32_t v)
{
    ObjectMesh::UpdateState& state = object.updateState;
    const uint32_t copy = uint32_t(state.vertexSource.size());
    state.vertexSource.push_back(state.vertexSource[v]);
    state.splitVertices.push_back(copy);
    mEdges.addVertex();
    ++object.stats.splitVertices;
    return copy;
}

uint32_t MeshBuilder::halfedgeOf(uint32_t from, uint32_t to) const
{
    const uint32_t e = mEdges.find(from, to);
    if (e == EdgeLists::kNone) return kNoIndex;
    return 2 * e + (mEdges.ends()[2 * size_t(e)] == from ? 0 : 1);
}

// A bit per corner on a directed edge that another face already runs along (OpenMesh's
// "complex edge").
unsigned MeshBuilder::conflicts(const uint32_t v[3]) const
{
    unsigned bad = 0;
    for (int k = 0; k < 3; ++k) {
        const int next = (k + 1) % 3;
        const uint32_t h = halfedgeOf(v[k], v[next]);
        if (h != kNoIndex && (mEdgeUsed[h >> 1] & (1u << (h & 1))))
            bad |= (1u << k) | (1u << next);
    }
    return bad;
}

// Adds face f on vertices v. After cutNonManifold() no directed edge is taken twice; should
// one be, the corners at fault go onto new copies (never drop a face).
void MeshBuilder::placeFace(ObjectMesh& object, uint32_t f, uint32_t v[3])
{
    if (const unsigned bad = conflicts(v)) {
        ++object.stats.splitFaces;
        for (int k = 0; k < 3; ++k) {
            if (bad & (1u << k)) v[k] = copyVertex(object, v[k]);
        }
    }
    for (int k = 0; k < 3; ++k) {
        const uint32_t a = v[k], b = v[(k + 1) % 3];
        uint32_t e = mEdges.find(a, b);
        if (e == EdgeLists::kNone) {
            e = mEdges.insert(a, b);
            mEdgeUsed.push_back(0);
        }
        const uint32_t h = 2 * e + (mEdges.ends()[2 * size_t(e)] == a ? 0 : 1);
        mEdgeUsed[e] |= uint8_t(1u << (h & 1));
        mFaceHalfedges[3 * size_t(f) + k] = h;
        object.faceVertices[3 * size_t(f) + k] = a;
    }
}

// Writes the edges and faces into OpenMesh's arrays: the halfedge 2e runs ends[2e] ->
// ends[2e+1]; a face's halfedge points to its corner 0, as add_face does.
void MeshBuilder::fillMesh(ObjectMesh& object)
{
    Mesh& mesh = object.mesh;
    const uint32_t vertexCount = uint32_t(object.updateState.vertexSource.size());
    const uint32_t edgeCount = uint32_t(mEdgeUsed.size());
    const uint32_t faceCount = uint32_t(object.faceVertices.size() / 3);
    const std::vector<uint32_t>& ends = mEdges.ends();
    mesh.clean();
    mesh.resize(vertexCount, edgeCount, faceCount);
    for (uint32_t e = 0; e < edgeCount; ++e) {
        mesh.set_vertex_handle(HalfedgeHandle(int(2 * e)), VertexHandle(int(ends[2 * e + 1])));
        mesh.set_vertex_handle(HalfedgeHandle(int(2 * e + 1)), VertexHandle(int(ends[2 * e])));
    }
    mCornerCount.assign(vertexCount, 0);
    for (uint32_t f = 0; f < faceCount; ++f) {
        const uint32_t* h = &mFaceHalfedges[3 * size_t(f)];
        const uint32_t* fv = &object.faceVertices[3 * size_t(f)];
        const FaceHandle fh{int(f)};
        for (int k = 0; k < 3; ++k) {
            const HalfedgeHandle heh{int(h[k])}; // braces: parentheses parse as a declaration
            mesh.set_face_handle(heh, fh);
            mesh.set_next_halfedge_handle(heh, HalfedgeHandle(int(h[(k + 1) % 3])));
            mesh.set_halfedge_handle(VertexHandle(int(fv[k])), heh); // outgoing from corner k
            ++mCornerCount[fv[k]];
        }
        mesh.set_halfedge_handle(fh, HalfedgeHandle(int(h[2])));
    }
}

// Links the boundary halfedges into loops and gives boundary vertices a boundary halfedge,
// which OpenMesh's circulators and is_boundary rely on. Returns false (and lists them in
// mFanVertices) when at some vertex several fans of faces meet: OpenMesh walks only one.
bool MeshBuilder::linkBoundaries(ObjectMesh& object)
{
    Mesh& mesh = object.mesh;
    const uint32_t vertexCount = uint32_t(mCornerCount.size());
    const uint32_t halfedgeCount = uint32_t(2 * mEdgeUsed.size());
    auto hasFace = [&](uint32_t h) { return (mEdgeUsed[h >> 1] >> (h & 1)) & 1u; };
    const std::vector<uint32_t>& ends = mEdges.ends();
    auto from = [&](uint32_t h) { return ends[h]; }; // 2e: ends[2e], 2e+1: ends[2e+1]
    auto next = [&](uint32_t h) {
        return uint32_t(mesh.next_halfedge_handle(HalfedgeHandle(int(h))).idx());
    };

    mOutBoundary.assign(vertexCount, kNoIndex);
    mFanVertices.clear();
    for (uint32_t h = 0; h < halfedgeCount; ++h) {
        if (hasFace(h)) continue;
        uint32_t& out = mOutBoundary[from(h)];
        if (out == kNoIndex) out = h;
        else mFanVertices.push_back(from(h)); // a second open fan
    }
    for (uint32_t v = 0; v < vertexCount; ++v) {
        const uint32_t corners = mCornerCount[v];
        uint32_t faces = 0;
        if (mOutBoundary[v] != kNoIndex) {
            // Open fan: from the face after the outgoing boundary to the incoming boundary.
            for (uint32_t h = mOutBoundary[v] ^ 1u; faces <= corners;) {
                ++faces;
                const uint32_t opposite = next(h) ^ 1u;
                if (!hasFace(opposite)) break;
                h = opposite;
            }
        } else {
            // Closed fan: around until the first outgoing halfedge comes back.
            const uint32_t first = uint32_t(mesh.halfedge_handle(VertexHandle(int(v))).idx());
            uint32_t h = first;
            do {
                ++faces;
                if (!hasFace(h ^ 1u)) {
                    faces = 0;
                    break;
                }
                h = next(h ^ 1u);
            } while (h != first && faces <= corners);
        }
        if (faces != corners) mFanVertices.push_back(v);
    }
    if (!mFanVertices.empty()) return false;

    for (uint32_t h = 0; h < halfedgeCount; ++h) {
        if (hasFace(h)) continue;
        const uint32_t to = from(h ^ 1u);
        mesh.set_next_halfedge_handle(HalfedgeHandle(int(h)),
                                      HalfedgeHandle(int(mOutBoundary[to])));
    }
    for (uint32_t v = 0; v < vertexCount; ++v) {
        if (mOutBoundary[v] != kNoIndex)
            mesh.set_halfedge_handle(VertexHandle(int(v)), HalfedgeHandle(int(mOutBoundary[v])));
    }
    return true;
}

// Safety net after cutNonManifold(): at each vertex of mFanVertices, the fan with the
// earliest face keeps the vertex and every other fan (faces around it that share edges) gets a
// copy. With everyFace, every face gets its own three vertices: the last resort.
void MeshBuilder::splitFans(ObjectMesh& object, bool everyFace)
{
    std::vector<uint32_t>& faceVertices = object.faceVertices;
    const uint32_t faceCount = uint32_t(faceVertices.size() / 3);
    if (everyFace) {
        for (uint32_t f = 1; f < faceCount; ++f) {
            for (int k = 0; k < 3; ++k)
                faceVertices[3 * f + k] = copyVertex(object, faceVertices[3 * f + k]);
            ++object.stats.splitFaces;
        }
        return;
    }

    std::sort(mFanVertices.begin(), mFanVertices.end());
    mFanVertices.erase(std::unique(mFanVertices.begin(), mFanVertices.end()), mFanVertices.end());
    std::vector<std::pair<uint32_t, uint32_t>> corners; // (vertex, face), by vertex then face
    for (uint32_t f = 0; f < faceCount; ++f) {
        for (int k = 0; k < 3; ++k) {
            const uint32_t v = faceVertices[3 * f + k];
            if (std::binary_search(mFanVertices.begin(), mFanVertices.end(), v))
                corners.emplace_back(v, f);
        }
    }
    std::sort(corners.begin(), corners.end());
    std::vector<uint32_t> root, copyOfRoot;
    for (size_t begin = 0; begin < corners.size();) {
        const uint32_t v = corners[begin].first;
        size_t end = begin;
        while (end < corners.size() && corners[end].first == v) ++end;
        const size_t n = end - begin;
        // Faces around v sharing another vertex share that edge: one fan. Valences are small.
        root.resize(n);
        for (size_t i = 0; i < n; ++i) root[i] = uint32_t(i);
        auto find = [&](uint32_t i) {
            while (root[i] != i) i = root[i] = root[root[i]];
            return i;
        };
        for (size_t i = 0; i < n; ++i) {
            const uint32_t* a = &faceVertices[3 * size_t(corners[begin + i].second)];
            for (size_t j = i + 1; j < n; ++j) {
                const uint32_t* b = &faceVertices[3 * size_t(corners[begin + j].second)];
                bool shared = false;
                for (int x = 0; x < 3 && !shared; ++x) {
                    for (int y = 0; y < 3 && !shared; ++y) shared = a[x] != v && a[x] == b[y];
                }
                if (!shared) continue;
                const uint32_t ri = find(uint32_t(i)), rj = find(uint32_t(j));
                if (ri != rj) root[std::max(ri, rj)] = std::min(ri, rj);
            }
        }
        copyOfRoot.assign(n, kNoIndex);
        for (size_t i = 0; i < n; ++i) {
            const uint32_t r = find(uint32_t(i));
            if (r == 0) continue; // the fan of the earliest face keeps v
            if (copyOfRoot[r] == kNoIndex) copyOfRoot[r] = copyVertex(object, v);
            uint32_t* fv = &faceVertices[3 * size_t(corners[begin + i].second)];
            for (int k = 0; k < 3; ++k) {
                if (fv[k] == v) fv[k] = copyOfRoot[r];
            }
            ++object.stats.splitFaces;
        }
        begin = end;
    }
}

bool MeshBuilder::connectFast(ObjectMesh& object)
{
    const uint32_t faceCount = uint32_t(object.faceVertices.size() / 3);
    mEdges.reset(object.updateState.vertexSource.size(), size_t(faceCount) * 3 / 2 + 16);
    mEdgeUsed.clear();
    mFaceHalfedges.resize(size_t(faceCount) * 3);
    for (uint32_t f = 0; f < faceCount; ++f) {
        uint32_t v[3] = {object.faceVertices[3 * size_t(f)], object.faceVertices[3 * size_t(f) + 1],
                         object.faceVertices[3 * size_t(f) + 2]};
        if (conflicts(v) != 0) return false;
        placeFace(object, f, v);
    }
    fillMesh(object);
    return linkBoundaries(object);
}

// Non-manifold input: an edge keeps its first face and the first later face that runs it the
// other way; any further face on it (a third sheet, a flipped or duplicated face) is cut off
// there. Then the corners at each vertex fall into fans, joined across the kept edges
// (union-find over all corners); the fan with the earliest corner keeps the vertex, every
// other fan gets a copy. A fin on a sheet stays one piece, and so does the sheet.
void MeshBuilder::cutNonManifold(ObjectMesh& object)
{
    std::vector<uint32_t>& faceVertices = object.faceVertices;
    const uint32_t cornerCount = uint32_t(faceVertices.size());
    const uint32_t vertexCount = uint32_t(object.updateState.vertexSource.size());
    mEdges.reset(vertexCount, cornerCount / 2 + 16);
    std::vector<uint32_t> first, second; // per edge: the corner starting its halfedge, or none
    for (uint32_t c = 0; c < cornerCount; ++c) {
        const uint32_t next = c % 3 == 2 ? c - 2 : c + 1;
        const uint32_t a = faceVertices[c], b = faceVertices[next];
        uint32_t e = mEdges.find(a, b);
        if (e == EdgeLists::kNone) {
            e = mEdges.insert(a, b);
            first.push_back(c);
            second.push_back(kNoIndex);
        } else if (second[e] == kNoIndex && faceVertices[first[e]] == b) {
            second[e] = c;
        }
    }
    std::vector<uint32_t> root(cornerCount);
    for (uint32_t c = 0; c < cornerCount; ++c) root[c] = c;
    auto find = [&](uint32_t c) {
        while (root[c] != c) c = root[c] = root[root[c]];
        return c;
    };
    auto join = [&](uint32_t a, uint32_t b) {
        a = find(a);
        b = find(b);
        if (a != b) root[std::max(a, b)] = std::min(a, b); // the earliest corner is the root
    };
    auto nextCorner = [](uint32_t c) { return c % 3 == 2 ? c - 2 : c + 1; };
    for (size_t e = 0; e < first.size(); ++e) {
        if (second[e] == kNoIndex) continue;
        // first runs a -> b from corner first[e]; second runs b -> a from corner second[e].
        join(first[e], nextCorner(second[e]));
        join(nextCorner(first[e]), second[e]);
    }
    std::vector<uint32_t> vertexOfRoot(cornerCount, kNoIndex);
    std::vector<uint8_t> taken(vertexCount, 0);
    uint32_t lastSplitFace = kNoIndex;
    for (uint32_t c = 0; c < cornerCount; ++c) {
        const uint32_t r = find(c);
        if (vertexOfRoot[r] == kNoIndex) {
            const uint32_t v = faceVertices[c];
            vertexOfRoot[r] = taken[v] ? copyVertex(object, v) : v;
            taken[v] = 1;
        }
        if (vertexOfRoot[r] != faceVertices[c] && c / 3 != lastSplitFace) {
            lastSplitFace = c / 3;
            ++object.stats.splitFaces;
        }
        faceVertices[c] = vertexOfRoot[r];
    }
}

void MeshBuilder::connect(ObjectMesh& object)
{
    if (connectFast(object)) return;
    cutNonManifold(object);
    const uint32_t faceCount = uint32_t(object.faceVertices.size() / 3);
    for (int round = 0;; ++round) {
        mEdges.reset(object.updateState.vertexSource.size(), size_t(faceCount) * 3 / 2 + 16);
        mEdgeUsed.clear();
        mFaceHalfedges.resize(size_t(faceCount) * 3);
        for (uint32_t f = 0; f < faceCount; ++f) {
            uint32_t v[3] = {object.faceVertices[3 * size_t(f)],
                             object.faceVertices[3 * size_t(f) + 1],
                             object.faceVertices[3 * size_t(f) + 2]};
            placeFace(object, f, v);
        }
        fillMesh(object);
        if (linkBoundaries(object)) return;
        splitFans(object, round + 1 >= kFanRounds);
    }
}

void MeshBuilder::buildEdges(ObjectMesh& object)
{
    const Mesh& mesh = object.mesh;
    const uint32_t edgeCount = uint32_t(mesh.n_edges());
    const uint32_t vertexCount = uint32_t(mesh.n_vertices());
    object.edges.resize(edgeCount);
    object.edgeClasses.resize(edgeCount);
    std::vector<uint32_t>& start = object.vertexEdgeStart;
    start.assign(vertexCount + 1, 0);
    for (uint32_t e = 0; e < edgeCount; ++e) {
        const HalfedgeHandle h0(int(2 * e)), h1(int(2 * e + 1));
        EdgeInfo& info = object.edges[e];
        info.v0 = uint32_t(mesh.to_vertex_handle(h1).idx());
        info.v1 = uint32_t(mesh.to_vertex_handle(h0).idx());
        const FaceHandle fh0 = mesh.face_handle(h0), fh1 = mesh.face_handle(h1);
        info.f0 = fh0.is_valid() ? uint32_t(fh0.idx()) : kNoIndex;
        info.f1 = fh1.is_valid() ? uint32_t(fh1.idx()) : kNoIndex;
        object.edgeClasses[e] = (fh0.is_valid() && fh1.is_valid()) ? 0 : kEdgeBorder;
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

    size_t total = 0;
    for (size_t b = 0; b < count; ++b) total += batches[b].vertices.size();
    object.sourceVertices.reserve(total);
    for (size_t b = 0; b < count; ++b) {
        const std::vector<Vertex>& vertices = batches[b].vertices;
        object.sourceVertices.insert(object.sourceVertices.end(), vertices.begin(),
                                     vertices.end());
        state.batchModes.push_back(assemblyMode(batches[b]));
        state.batchCounts.push_back(uint32_t(vertices.size()));
    }
    state.batchMaterials.resize(count);
    stats.batches = uint32_t(count);
    stats.sourceVertices = uint32_t(total);
    const Vertex* sources = object.sourceVertices.data();

    glm::vec3 lo(FLT_MAX), hi(-FLT_MAX);
    for (size_t i = 0; i < total; ++i) {
        const glm::vec3& p = sources[i].position;
        if (!isFinite(p)) continue;
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const float diagonal = lo.x <= hi.x ? glm::length(hi - lo) : 0.0f;
    state.weldTolerance = std::isfinite(diagonal) ? params.weldTolerance * diagonal : 0.0f;
    state.updateTolerance = std::isfinite(diagonal)
                                ? std::max(params.updateTolerance, params.weldTolerance) * diagonal
                                : 0.0f;
    stats.weldedVertices =
        mWelder.weld(sources, total, lo, hi, state.weldTolerance, state.weld, state.weldRep);

    // Assembly: keep the triangles with three finite, distinct, non-collinear corners.
    const uint32_t* weld = state.weld.data();
    mTriangles.clear();
    uint32_t base = 0;
    for (size_t b = 0; b < count; ++b) {
        const uint32_t n = state.batchCounts[b];
        const bool clockwise = batches[b].clockwise;
        stats.incompleteVertices += assembleTriangles(
            batches[b].mode, n, [&](uint32_t i0, uint32_t i1, uint32_t i2) {
                if (clockwise) std::swap(i1, i2);
                i0 += base;
                i1 += base;
                i2 += base;
                ++stats.triangles;
                const uint32_t w0 = weld[i0], w1 = weld[i1], w2 = weld[i2];
                if (w0 == kNoIndex || w1 == kNoIndex || w2 == kNoIndex) {
                    ++stats.nonFiniteTriangles;
                } else if (w0 == w1 || w1 == w2 || w0 == w2) {
                    ++stats.degenerateTriangles;
                } else if (zeroArea(sources[i0].position, sources[i1].position,
                                    sources[i2].position)) {
                    ++stats.degenerateTriangles;
                    state.areaDropped.insert(state.areaDropped.end(), {i0, i1, i2});
                } else {
                    mTriangles.insert(mTriangles.end(), {i0, i1, i2});
                }
            },
            batches[b].quadCut);
        state.batchFaceEnd.push_back(uint32_t(mTriangles.size() / 3));
        base += n;
    }
    const uint32_t faceCount = uint32_t(mTriangles.size() / 3);

    // Vertices in order of first use; every kept triangle becomes a face, in drawing order.
    state.weldVertex.assign(stats.weldedVertices, kNoIndex);
    state.vertexSource.reserve(stats.weldedVertices);
    object.faceVertices.resize(mTriangles.size());
    for (size_t c = 0; c < mTriangles.size(); ++c)
        object.faceVertices[c] = vertexFor(object, weld[mTriangles[c]]);
    connect(object);

    object.faceCorners.assign(mTriangles.begin(), mTriangles.end());
    object.faceMaterials.resize(faceCount);
    fillMaterials(object, batches, count);
    buildEdges(object);
    gatherSources(object, mGeometry);
    computeGeometry(object, params.creaseCosine, mGeometry);
    return result;
}

bool MeshBuilder::prepareUpdate(const ObjectMesh& object, const Batch* batches, size_t count)
{
    const ObjectMesh::UpdateState& state = object.updateState;
    if (count != state.batchModes.size()) return false;
    for (size_t b = 0; b < count; ++b) {
        if (assemblyMode(batches[b]) != state.batchModes[b]) return false;
        if (batches[b].vertices.size() != state.batchCounts[b]) return false;
    }
    // One pass, a batch at a time while it is in the cache: copy, check, gather.
    mStaged.clear();
    mStaged.reserve(object.sourceVertices.size());
    mGeometry.prepare(object.mesh.n_vertices());
    mGeometry.areaSum.reserve(object.mesh.n_vertices()); // applyUpdate must not allocate
    const float tol2 = state.updateTolerance * state.updateTolerance;
    const uint32_t* weld = state.weld.data();
    const uint32_t* rep = state.weldRep.data();
    uint32_t i = 0;
    for (size_t b = 0; b < count; ++b) {
        const std::vector<Vertex>& vertices = batches[b].vertices;
        mStaged.insert(mStaged.end(), vertices.begin(), vertices.end());
        const Vertex* staged = mStaged.data();
        for (const uint32_t end = i + uint32_t(vertices.size()); i < end; ++i) {
            const Vertex& source = staged[i];
            const uint32_t w = weld[i];
            const bool finite = isFinite(source.position);
            if (w == kNoIndex) {
                if (finite) return false;
                continue;
            }
            if (!finite) return false;
            const uint32_t r = rep[w];
            if (r != i) {
                const glm::vec3 d = source.position - staged[r].position;
                if (!(glm::dot(d, d) <= tol2)) return false;
            }
            mGeometry.add(state, source, i, w);
        }
    }
    const Vertex* staged = mStaged.data();
    const std::vector<uint32_t>& dropped = state.areaDropped;
    for (size_t t = 0; t + 2 < dropped.size(); t += 3) {
        if (!zeroArea(staged[dropped[t]].position, staged[dropped[t + 1]].position,
                      staged[dropped[t + 2]].position))
            return false;
    }
    mGeometry.addSplitVertices(state, staged);
    return true;
}

void MeshBuilder::applyUpdate(ObjectMesh& object, const Batch* batches, size_t count,
                              const ReconstructParams& params)
{
    object.sourceVertices.swap(mStaged);
    for (size_t b = 0; b < count; ++b) {
        if (batches[b].materialId != object.updateState.batchMaterials[b]) {
            fillMaterials(object, batches, count);
            break;
        }
    }
    ++object.geometryVersion;
    computeGeometry(object, params.creaseCosine, mGeometry);
}

} // namespace nprgl::reconstruct
