// Reconstruction: primitive assembly, grouping, welding, connectivity with non-manifold input,
// normals, edge classes, silhouettes, caches and export. Pure C++, no GL context.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <GL/gl.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>

#include "reconstruct/MeshExport.h"
#include "reconstruct/PrimitiveAssembly.h"
#include "reconstruct/Reconstructor.h"
#include "reconstruct/Silhouette.h"

namespace nprgl::reconstruct {
namespace {

constexpr float kPi = 3.14159265358979f;

Vertex vertex(glm::vec3 p, glm::vec3 n = glm::vec3(0.0f), bool hasNormal = false)
{
    Vertex v{};
    v.position = p;
    v.normal = n;
    v.color = glm::vec4(1.0f);
    v.hasNormal = hasNormal;
    return v;
}

Batch batch(uint32_t mode, std::vector<Vertex> vertices, uint32_t material = 0,
            glm::mat4 modelview = glm::mat4(1.0f))
{
    Batch b;
    b.mode = mode;
    b.vertices = std::move(vertices);
    b.modelview = modelview;
    b.materialId = material;
    b.contentHash = hashBatch(b);
    return b;
}

void rehash(std::vector<Batch>& batches)
{
    for (Batch& b : batches) b.contentHash = hashBatch(b);
}

// A cube [-s, s]^3 as six GL_QUADS batches, counter-clockwise from outside, with face normals.
std::vector<Batch> cube(float s = 1.0f, glm::vec3 offset = glm::vec3(0.0f),
                        uint32_t topMaterial = 0)
{
    const glm::vec3 normals[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0},
                                  {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const glm::vec3 firstAxis[6] = {{0, 1, 0}, {0, 0, 1}, {0, 0, 1},
                                    {1, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    std::vector<Batch> batches;
    for (int i = 0; i < 6; ++i) {
        const glm::vec3 n = normals[i], u = firstAxis[i], v = glm::cross(n, u);
        const glm::vec3 c = offset + s * n;
        std::vector<Vertex> quad = {vertex(c + s * (-u - v), n, true),
                                    vertex(c + s * (u - v), n, true),
                                    vertex(c + s * (u + v), n, true),
                                    vertex(c + s * (-u + v), n, true)};
        batches.push_back(batch(GL_QUADS, quad, n.y > 0 ? topMaterial : 0));
    }
    return batches;
}

// A torus (major radius R, minor r) as one GL_QUAD_STRIP per ring; the seam (angle 2*pi) is
// computed, not copied, so it only welds with the tolerance.
std::vector<Batch> torus(int rings, int sides, float R = 2.0f, float r = 0.5f)
{
    auto point = [&](int i, int j) {
        const float theta = 2.0f * kPi * float(i) / float(rings);
        const float phi = 2.0f * kPi * float(j) / float(sides);
        return glm::vec3((R + r * std::cos(phi)) * std::cos(theta),
                         (R + r * std::cos(phi)) * std::sin(theta), r * std::sin(phi));
    };
    std::vector<Batch> batches;
    for (int i = 0; i < rings; ++i) {
        std::vector<Vertex> strip;
        for (int j = 0; j <= sides; ++j) {
            strip.push_back(vertex(point(i, j)));
            strip.push_back(vertex(point(i + 1, j)));
        }
        batches.push_back(batch(GL_QUAD_STRIP, strip));
    }
    return batches;
}

// A UV sphere: latitude bands as GL_TRIANGLE_STRIP batches, the poles as GL_TRIANGLE_FAN.
std::vector<Batch> sphere(int slices, int stacks, float radius = 1.0f, bool normals = true)
{
    auto point = [&](int k, int j) {
        const float phi = kPi * float(k) / float(stacks);
        const float theta = 2.0f * kPi * float(j) / float(slices);
        const glm::vec3 n(std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta),
                          std::cos(phi));
        return vertex(radius * n, n, normals);
    };
    std::vector<Batch> batches;
    std::vector<Vertex> north = {point(0, 0)};
    for (int j = 0; j <= slices; ++j) north.push_back(point(1, j));
    batches.push_back(batch(GL_TRIANGLE_FAN, north));
    for (int k = 1; k + 1 < stacks; ++k) {
        std::vector<Vertex> band;
        for (int j = 0; j <= slices; ++j) {
            band.push_back(point(k, j));
            band.push_back(point(k + 1, j));
        }
        batches.push_back(batch(GL_TRIANGLE_STRIP, band));
    }
    std::vector<Vertex> south = {point(stacks, 0)};
    for (int j = slices; j >= 0; --j) south.push_back(point(stacks - 1, j));
    batches.push_back(batch(GL_TRIANGLE_FAN, south));
    return batches;
}

std::shared_ptr<const ObjectMesh> single(Reconstructor& r, const std::vector<Batch>& batches)
{
    const std::vector<FrameObject> objects = r.build(batches);
    EXPECT_EQ(objects.size(), 1u);
    return objects.empty() ? nullptr : objects[0].mesh;
}

// Every face's normal points away from `centre` (winding kept through assembly and welding).
void expectOutward(const ObjectMesh& m, glm::vec3 centre = glm::vec3(0.0f))
{
    for (uint32_t f = 0; f < m.faceCount(); ++f) {
        const glm::vec3 c = (m.position(m.faceVertices[3 * f]) +
                             m.position(m.faceVertices[3 * f + 1]) +
                             m.position(m.faceVertices[3 * f + 2])) /
                            3.0f;
        ASSERT_GT(glm::dot(m.faceNormal(f), c - centre), 0.0f) << "face " << f;
    }
}

std::vector<glm::uvec3> triangles(uint32_t mode, uint32_t count, uint32_t* leftover = nullptr,
                                  QuadCut cut = QuadCut::V0V2)
{
    std::vector<glm::uvec3> out;
    const uint32_t left = assembleTriangles(
        mode, count, [&](uint32_t a, uint32_t b, uint32_t c) { out.emplace_back(a, b, c); }, cut);
    if (leftover) *leftover = left;
    return out;
}

TEST(Assembly, EveryModeWithGlWinding)
{
    uint32_t left = 0;
    EXPECT_EQ(triangles(GL_TRIANGLES, 7, &left),
              (std::vector<glm::uvec3>{{0, 1, 2}, {3, 4, 5}}));
    EXPECT_EQ(left, 1u);
    EXPECT_EQ(triangles(GL_TRIANGLE_STRIP, 5),
              (std::vector<glm::uvec3>{{0, 1, 2}, {2, 1, 3}, {2, 3, 4}}));
    EXPECT_EQ(triangles(GL_TRIANGLE_FAN, 5),
              (std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}));
    EXPECT_EQ(triangles(GL_POLYGON, 4), (std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 3}}));
    EXPECT_EQ(triangles(GL_QUADS, 9, &left),
              (std::vector<glm::uvec3>{{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}}));
    EXPECT_EQ(left, 1u);
    EXPECT_EQ(triangles(GL_QUADS, 8, &left, QuadCut::V1V3),
              (std::vector<glm::uvec3>{{0, 1, 3}, {1, 2, 3}, {4, 5, 7}, {5, 6, 7}}));
    EXPECT_EQ(triangles(GL_QUAD_STRIP, 7, &left),
              (std::vector<glm::uvec3>{{0, 1, 3}, {0, 3, 2}, {2, 3, 5}, {2, 5, 4}}));
    EXPECT_EQ(left, 1u);
    EXPECT_TRUE(triangles(GL_TRIANGLE_STRIP, 2, &left).empty());
    EXPECT_EQ(left, 2u);
    EXPECT_TRUE(triangles(GL_LINES, 6, &left).empty());
    EXPECT_EQ(left, 6u);
}

// The same vertices cut along the other diagonal are other triangles: a batch whose cut
// changes is a new mesh, not an update of the old one's positions.
TEST(Assembly, TheQuadCutIsPartOfWhatABatchIs)
{
    Batch a = batch(GL_QUADS, {vertex({0, 0, 0}), vertex({1, 0, 0}), vertex({1, 1, 0.5f}),
                               vertex({0, 1, 0})});
    Batch b = a;
    b.quadCut = QuadCut::V1V3;
    EXPECT_NE(assemblyMode(a), assemblyMode(b));
    EXPECT_NE(hashBatch(a), hashBatch(b));
}

TEST(Assembly, StripKeepsOrientation)
{
    // A planar zig-zag strip: every triangle must face +z.
    std::vector<Vertex> strip;
    for (int i = 0; i < 8; ++i)
        strip.push_back(vertex(glm::vec3(float(i / 2), float(1 - i % 2), 0)));
    Reconstructor r;
    const auto m = single(r, {batch(GL_TRIANGLE_STRIP, strip)});
    ASSERT_EQ(m->faceCount(), 6u);
    for (uint32_t f = 0; f < 6; ++f) EXPECT_GT(m->faceNormal(f).z, 0.99f) << f;
    EXPECT_EQ(m->stats.splitFaces, 0u);
}

TEST(Reconstruct, CubeFromSixQuadBatches)
{
    Reconstructor r;
    const auto m = single(r, cube());
    ASSERT_TRUE(m);
    EXPECT_EQ(m->vertexCount(), 8u);
    EXPECT_EQ(m->edgeCount(), 18u);
    EXPECT_EQ(m->faceCount(), 12u);
    EXPECT_EQ(m->mesh.n_faces(), 12u);
    EXPECT_TRUE(m->closed());
    EXPECT_EQ(m->eulerCharacteristic(), 2);
    EXPECT_EQ(m->stats.batches, 6u);
    EXPECT_EQ(m->stats.weldedVertices, 8u);
    EXPECT_EQ(m->stats.splitFaces, 0u);
    EXPECT_EQ(m->stats.degenerateTriangles + m->stats.nonFiniteTriangles, 0u);
    expectOutward(*m);
    // Program normals are per corner: each face's corners carry its own normal.
    for (uint32_t f = 0; f < 12; ++f) {
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(glm::dot(m->corner(f, k).normal, m->faceNormal(f)), 1.0f, 1e-6f);
    }
    for (uint32_t v = 0; v < 8; ++v) {
        EXPECT_NEAR(glm::length(m->vertexNormal(v)), 1.0f, 1e-5f);
        EXPECT_GT(glm::dot(m->vertexNormal(v), m->position(v)), 0.0f);
    }
}

TEST(Reconstruct, CubeCreasesAreTheTwelveBoxEdges)
{
    Reconstructor r;
    const auto m = single(r, cube());
    ASSERT_TRUE(m);
    int creases = 0;
    for (uint32_t i = 0; i < m->edgeCount(); ++i) {
        const EdgeInfo& e = m->edges[i];
        const uint8_t classes = m->edgeClasses[i];
        const glm::vec3 d = glm::abs(m->position(e.v0) - m->position(e.v1));
        const int axes = (d.x > 0.5f) + (d.y > 0.5f) + (d.z > 0.5f);
        if (classes & kEdgeCrease) {
            ++creases;
            EXPECT_EQ(axes, 1) << "a crease that is not a box edge";
        } else {
            EXPECT_EQ(axes, 2) << "a box edge that is not a crease";
        }
        EXPECT_FALSE(classes & kEdgeBorder);
        EXPECT_FALSE(classes & kEdgeMaterial);
    }
    EXPECT_EQ(creases, 12);
}

TEST(Reconstruct, MaterialBoundaryEdges)
{
    Reconstructor r;
    const auto m = single(r, cube(1.0f, glm::vec3(0.0f), 7));
    ASSERT_TRUE(m);
    int material = 0;
    for (uint32_t i = 0; i < m->edgeCount(); ++i) {
        const EdgeInfo& e = m->edges[i];
        if (!(m->edgeClasses[i] & kEdgeMaterial)) continue;
        ++material;
        // The top face's four box edges, at y = 1.
        EXPECT_FLOAT_EQ(m->position(e.v0).y, 1.0f);
        EXPECT_FLOAT_EQ(m->position(e.v1).y, 1.0f);
        EXPECT_NE(m->faceMaterials[e.f0], m->faceMaterials[e.f1]);
    }
    EXPECT_EQ(material, 4);
}

TEST(Reconstruct, TorusFromQuadStrips)
{
    Reconstructor r;
    const int rings = 24, sides = 12;
    const auto m = single(r, torus(rings, sides));
    ASSERT_TRUE(m);
    EXPECT_EQ(m->vertexCount(), uint32_t(rings * sides));
    EXPECT_EQ(m->faceCount(), uint32_t(2 * rings * sides));
    EXPECT_EQ(m->edgeCount(), uint32_t(3 * rings * sides));
    EXPECT_TRUE(m->closed());
    EXPECT_EQ(m->eulerCharacteristic(), 0);
    EXPECT_EQ(m->stats.splitFaces, 0u);
    // Outward: away from the tube's centre circle.
    for (uint32_t f = 0; f < m->faceCount(); ++f) {
        const glm::vec3 c = m->position(m->faceVertices[3 * f]);
        const glm::vec3 axis = 2.0f * glm::normalize(glm::vec3(c.x, c.y, 0.0f));
        ASSERT_GT(glm::dot(m->faceNormal(f), c - axis), 0.0f) << f;
    }
}

TEST(Reconstruct, TorusSeamNeedsTheTolerance)
{
    // With exact welding the computed seam (angle 2*pi) stays open.
    ReconstructParams exact;
    exact.weldTolerance = 0.0f;
    Reconstructor r(exact);
    const auto m = single(r, torus(24, 12));
    ASSERT_TRUE(m);
    EXPECT_FALSE(m->closed());
}

TEST(Reconstruct, SphereFromBandsAndFans)
{
    Reconstructor r;
    const int slices = 24, stacks = 12;
    const auto m = single(r, sphere(slices, stacks));
    ASSERT_TRUE(m);
    EXPECT_EQ(m->stats.batches, uint32_t(stacks));
    EXPECT_EQ(m->vertexCount(), uint32_t(2 + slices * (stacks - 1)));
    EXPECT_EQ(m->faceCount(), uint32_t(2 * slices * (stacks - 1)));
    EXPECT_TRUE(m->closed());
    EXPECT_EQ(m->eulerCharacteristic(), 2);
    EXPECT_EQ(m->stats.splitFaces, 0u);
    EXPECT_EQ(m->stats.degenerateTriangles, 0u);
    expectOutward(*m);
    // The program's normals (exact radial) become the vertex normals.
    for (uint32_t v = 0; v < m->vertexCount(); ++v)
        EXPECT_NEAR(glm::dot(m->vertexNormal(v), glm::normalize(m->position(v))), 1.0f, 1e-5f);
    // No crease on a smooth sphere, no border.
    for (const uint8_t classes : m->edgeClasses) EXPECT_EQ(classes, 0) << "edge classes";
}

TEST(Reconstruct, AreaWeightedNormalsWithoutProgramNormals)
{
    Reconstructor r;
    const auto m = single(r, sphere(32, 16, 1.0f, false));
    ASSERT_TRUE(m);
    for (uint32_t v = 0; v < m->vertexCount(); ++v)
        EXPECT_GT(glm::dot(m->vertexNormal(v), glm::normalize(m->position(v))), 0.995f) << v;
}

TEST(Reconstruct, CancellingProgramNormalsFallBackToFaceNormals)
{
    // Two triangles (both facing +z) whose program normals disagree: +z on the first, -z on
    // the second. The shared edge's vertices get the face-based normal.
    const glm::vec3 up(0, 0, 1), down(0, 0, -1);
    const std::vector<Vertex> tris = {
        vertex({0, 0, 0}, up, true), vertex({1, 0, 0}, up, true), vertex({0, 1, 0}, up, true),
        vertex({1, 0, 0}, down, true), vertex({1, 1, 0}, down, true),
        vertex({0, 1, 0}, down, true)};
    Reconstructor r;
    const auto m = single(r, {batch(GL_TRIANGLES, tris)});
    ASSERT_TRUE(m);
    ASSERT_EQ(m->vertexCount(), 4u);
    for (uint32_t v = 0; v < 4; ++v) {
        const glm::vec3 p = m->position(v);
        const glm::vec3 expected = p == glm::vec3(0, 0, 0) ? up
                                   : p == glm::vec3(1, 1, 0) ? down
                                                             : up; // shared: from the faces
        EXPECT_EQ(m->vertexNormal(v), expected) << p.x << "," << p.y;
    }
}

TEST(Reconstruct, ConsecutiveBatchesWithOneModelviewAreOneObject)
{
    const glm::mat4 a(1.0f);
    const glm::mat4 b = glm::mat4(1.0f) + glm::mat4(0.0f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                                                    1, 0, 0, 0); // translated in x
    std::vector<Batch> frame;
    for (Batch& q : cube()) {
        q.modelview = a;
        frame.push_back(q);
    }
    for (Batch& q : cube()) {
        q.modelview = b;
        frame.push_back(q);
    }
    Reconstructor r;
    const auto objects = r.build(frame);
    ASSERT_EQ(objects.size(), 2u);
    EXPECT_EQ(objects[0].firstBatch, 0u);
    EXPECT_EQ(objects[0].batchCount, 6u);
    EXPECT_EQ(objects[1].firstBatch, 6u);
    EXPECT_EQ(objects[1].batchCount, 6u);
    EXPECT_EQ(objects[0].modelview, a);
    EXPECT_EQ(objects[1].modelview, b);
    for (const FrameObject& o : objects) EXPECT_EQ(o.mesh->vertexCount(), 8u);
    // The same geometry: one cached mesh serves both.
    EXPECT_EQ(objects[0].mesh, objects[1].mesh);

    // Only consecutive batches group: a, b, a is three objects.
    std::vector<Batch> interleaved = {frame[0], frame[6], frame[1]};
    EXPECT_EQ(r.build(interleaved).size(), 3u);
}

TEST(Reconstruct, BowTieKeepsBothFacesOnSplitVertices)
{
    // Two triangles meeting at the origin only.
    const std::vector<Vertex> tris = {
        vertex({0, 0, 0}), vertex({1, 0, 0}),  vertex({1, 1, 0}),
        vertex({0, 0, 0}), vertex({-1, 0, 0}), vertex({-1, -1, 0})};
    Reconstructor r;
    const auto m = single(r, {batch(GL_TRIANGLES, tris)});
    ASSERT_TRUE(m);
    EXPECT_EQ(m->faceCount(), 2u);
    EXPECT_EQ(m->mesh.n_faces(), 2u);
    EXPECT_EQ(m->stats.weldedVertices, 5u);
    EXPECT_EQ(m->vertexCount(), 6u);
    EXPECT_EQ(m->stats.splitVertices, 1u);
    EXPECT_EQ(m->stats.splitFaces, 1u);
    for (auto vh : m->mesh.vertices()) EXPECT_TRUE(m->mesh.is_manifold(vh));
    EXPECT_EQ(m->position(m->faceVertices[0]), m->position(m->faceVertices[3]));
}

TEST(Reconstruct, EdgeWithThreeFacesKeepsAllFaces)
{
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0.5f, 1, 0), d(0.5f, -1, 0), e(0.5f, 0, 1);
    const std::vector<Vertex> tris = {vertex(a), vertex(b), vertex(c),  // a->b
                                      vertex(b), vertex(a), vertex(d),  // b->a: manifold pair
                                      vertex(b), vertex(a), vertex(e)}; // b->a again: third face
    Reconstructor r;
    const auto m = single(r, {batch(GL_TRIANGLES, tris)});
    ASSERT_TRUE(m);
    EXPECT_EQ(m->faceCount(), 3u);
    EXPECT_EQ(m->mesh.n_faces(), 3u);
    EXPECT_EQ(m->stats.splitFaces, 1u);
    EXPECT_EQ(m->stats.splitVertices, 2u); // a and b copied for the third face
    EXPECT_EQ(m->vertexCount(), 7u);
    EXPECT_EQ(m->edgeCount(), 8u);
}

TEST(Reconstruct, InconsistentWindingAndDuplicatesKeepAllFaces)
{
    const glm::vec3 a(0, 0, 0), b(1, 0, 0), c(0.5f, 1, 0), d(0.5f, -1, 0);
    // The second triangle runs a->b like the first: "complex edge" for OpenMesh.
    const std::vector<Vertex> flipped = {vertex(a), vertex(b), vertex(c),
                                         vertex(a), vertex(b), vertex(d)};
    // The same triangle three times.
    const std::vector<Vertex> duplicated = {vertex(a), vertex(b), vertex(c), vertex(a),
                                            vertex(b), vertex(c), vertex(a), vertex(b),
                                            vertex(c)};
    Reconstructor r;
    const auto m1 = single(r, {batch(GL_TRIANGLES, flipped)});
    ASSERT_TRUE(m1);
    EXPECT_EQ(m1->faceCount(), 2u);
    EXPECT_EQ(m1->mesh.n_faces(), 2u);
    EXPECT_EQ(m1->stats.splitFaces, 1u);
    const auto m2 = single(r, {batch(GL_TRIANGLES, duplicated)});
    ASSERT_TRUE(m2);
    EXPECT_EQ(m2->faceCount(), 3u);
    EXPECT_EQ(m2->mesh.n_faces(), 3u);
    EXPECT_EQ(m2->stats.splitFaces, 2u);
}

// The halfedge structure is what OpenMesh's own add_face would have made: consistent next,
// prev, opposite, faces and boundary loops, one fan per vertex.
void expectValidConnectivity(const ObjectMesh& m)
{
    const Mesh& mesh = m.mesh;
    ASSERT_EQ(mesh.n_faces(), m.faceCount());
    for (auto heh : mesh.halfedges()) {
        ASSERT_EQ(mesh.next_halfedge_handle(mesh.prev_halfedge_handle(heh)), heh);
        ASSERT_EQ(mesh.to_vertex_handle(heh),
                  mesh.from_vertex_handle(mesh.next_halfedge_handle(heh)));
        ASSERT_EQ(mesh.face_handle(mesh.next_halfedge_handle(heh)), mesh.face_handle(heh));
        ASSERT_FALSE(mesh.face_handle(heh).is_valid() &&
                     mesh.face_handle(heh) == mesh.opposite_face_handle(heh));
    }
    for (uint32_t f = 0; f < m.faceCount(); ++f) {
        auto heh = mesh.halfedge_handle(OpenMesh::FaceHandle(int(f)));
        for (int k = 0; k < 3; ++k) {
            ASSERT_EQ(uint32_t(mesh.to_vertex_handle(heh).idx()), m.faceVertices[3 * f + k]);
            heh = mesh.next_halfedge_handle(heh);
        }
        ASSERT_EQ(heh, mesh.halfedge_handle(OpenMesh::FaceHandle(int(f))));
    }
    std::vector<int> corners(mesh.n_vertices(), 0);
    for (uint32_t v : m.faceVertices) ++corners[v];
    for (auto vh : mesh.vertices()) {
        ASSERT_GT(corners[vh.idx()], 0) << "isolated vertex";
        ASSERT_EQ(mesh.from_vertex_handle(mesh.halfedge_handle(vh)), vh);
        ASSERT_TRUE(mesh.is_manifold(vh));
        int faces = 0;
        for (auto fh : mesh.vf_range(vh)) faces += fh.is_valid() ? 1 : 0;
        ASSERT_EQ(faces, corners[vh.idx()]) << "a fan OpenMesh does not walk";
    }
}

// Connected components of the face graph (faces sharing an edge).
int faceComponents(const ObjectMesh& m)
{
    std::vector<int> component(m.faceCount(), -1);
    int count = 0;
    for (uint32_t start = 0; start < m.faceCount(); ++start) {
        if (component[start] >= 0) continue;
        std::vector<uint32_t> stack = {start};
        component[start] = count;
        while (!stack.empty()) {
            const uint32_t f = stack.back();
            stack.pop_back();
            for (auto g : m.mesh.ff_range(OpenMesh::FaceHandle(int(f)))) {
                if (component[g.idx()] < 0) {
                    component[g.idx()] = count;
                    stack.push_back(uint32_t(g.idx()));
                }
            }
        }
        ++count;
    }
    return count;
}

TEST(Reconstruct, FinOnASheetIsCutOffInOnePiece)
{
    // Two quads either side of the chain y = 0 (a flat sheet facing +z) and a vertical fin of
    // two quads standing on the same chain: three faces on each chain edge.
    std::vector<Vertex> a, b, c;
    for (int i = 0; i < 2; ++i) {
        const float x0 = float(i), x1 = float(i + 1);
        for (glm::vec3 p : {glm::vec3(x0, -1, 0), glm::vec3(x1, -1, 0), glm::vec3(x1, 0, 0),
                            glm::vec3(x0, 0, 0)})
            a.push_back(vertex(p));
        for (glm::vec3 p : {glm::vec3(x0, 0, 0), glm::vec3(x1, 0, 0), glm::vec3(x1, 1, 0),
                            glm::vec3(x0, 1, 0)})
            b.push_back(vertex(p));
        for (glm::vec3 p : {glm::vec3(x0, 0, 0), glm::vec3(x1, 0, 0), glm::vec3(x1, 0, 1),
                            glm::vec3(x0, 0, 1)})
            c.push_back(vertex(p));
    }
    Reconstructor r;
    const auto m = single(r, {batch(GL_QUADS, a), batch(GL_QUADS, b), batch(GL_QUADS, c)});
    ASSERT_TRUE(m);
    EXPECT_EQ(m->faceCount(), 12u);
    EXPECT_EQ(m->mesh.n_faces(), 12u);
    EXPECT_EQ(m->stats.weldedVertices, 12u);
    EXPECT_EQ(m->stats.splitVertices, 3u); // the fin's copy of the chain
    EXPECT_EQ(m->stats.splitFaces, 4u);    // the fin's four triangles
    EXPECT_EQ(m->vertexCount(), 15u);
    EXPECT_EQ(faceComponents(*m), 2);      // the sheet and the fin, each in one piece
    expectValidConnectivity(*m);
    for (auto vh : m->mesh.vertices()) EXPECT_TRUE(m->mesh.is_manifold(vh));
    // The sheet's chain edges are interior; the fin's foot is a border.
    int chainBorders = 0;
    for (uint32_t e = 0; e < m->edgeCount(); ++e) {
        const glm::vec3 p0 = m->position(m->edges[e].v0), p1 = m->position(m->edges[e].v1);
        if (p0.y == 0 && p1.y == 0 && p0.z == 0 && p1.z == 0)
            chainBorders += (m->edgeClasses[e] & kEdgeBorder) ? 1 : 0;
    }
    EXPECT_EQ(chainBorders, 2);
}

TEST(Reconstruct, TwoClosedFansAtOneVertexAreSplit)
{
    // Two tetrahedra touching at the origin only: OpenMesh cannot walk two closed fans.
    auto tetrahedron = [](glm::vec3 b0, glm::vec3 b1, glm::vec3 b2) {
        const glm::vec3 p[4] = {glm::vec3(0.0f), b0, b1, b2};
        const glm::vec3 centre = (p[0] + p[1] + p[2] + p[3]) / 4.0f;
        const int faces[4][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
        std::vector<Vertex> out;
        for (const auto& f : faces) {
            glm::vec3 x = p[f[0]], y = p[f[1]], z = p[f[2]];
            if (glm::dot(glm::cross(y - x, z - x), (x + y + z) / 3.0f - centre) < 0)
                std::swap(y, z);
            for (glm::vec3 q : {x, y, z}) out.push_back(vertex(q));
        }
        return out;
    };
    Reconstructor r;
    const auto m = single(r, {batch(GL_TRIANGLES, tetrahedron({-1, 0, 0}, {-1, 1, 0}, {-1, 0, 1})),
                              batch(GL_TRIANGLES, tetrahedron({1, 0, 0}, {1, 0, 1}, {1, 1, 0}))});
    ASSERT_TRUE(m);
    EXPECT_EQ(m->faceCount(), 8u);
    EXPECT_EQ(m->stats.weldedVertices, 7u);
    EXPECT_EQ(m->vertexCount(), 8u);
    EXPECT_EQ(m->stats.splitVertices, 1u);
    EXPECT_EQ(m->stats.splitFaces, 3u);
    EXPECT_TRUE(m->closed());
    EXPECT_EQ(m->eulerCharacteristic(), 4); // two spheres
    EXPECT_EQ(faceComponents(*m), 2);
}

TEST(Reconstruct, RandomSoupsKeepEveryFaceOnValidConnectivity)
{
    // Triangles on a few random grid points: bow-ties, three to many faces per edge, flipped
    // and duplicated faces, all at once.
    uint32_t seed = 12345;
    auto rnd = [&seed](uint32_t n) {
        seed = seed * 1664525u + 1013904223u;
        return (seed >> 8) % n;
    };
    for (int trial = 0; trial < 40; ++trial) {
        std::vector<Vertex> tris;
        const uint32_t points = 4 + rnd(20), count = 1 + rnd(60);
        for (uint32_t t = 0; t < 3 * count; ++t) {
            const uint32_t i = rnd(points);
            tris.push_back(vertex(glm::vec3(float(i % 3), float(i / 3 % 3), float(i / 9))));
        }
        Reconstructor r;
        const auto m = single(r, {batch(GL_TRIANGLES, tris)});
        ASSERT_TRUE(m);
        SCOPED_TRACE(trial);
        EXPECT_EQ(m->faceCount(), m->stats.triangles - m->stats.degenerateTriangles);
        expectValidConnectivity(*m);
    }
}

TEST(Reconstruct, NonFiniteTrianglesAreDroppedAndCounted)
{
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    const std::vector<Vertex> tris = {
        vertex({0, 0, 0}),   vertex({1, 0, 0}), vertex({0, 1, 0}),   // kept
        vertex({nan, 0, 0}), vertex({1, 0, 0}), vertex({0, 1, 0}),   // NaN
        vertex({0, 0, 0}),   vertex({1, inf, 0}), vertex({0, 1, 0})}; // Inf
    // A strip whose first vertex is NaN loses only its first triangle.
    const std::vector<Vertex> strip = {vertex({nan, nan, nan}), vertex({0, 0, 1}),
                                       vertex({1, 0, 1}),       vertex({0, 1, 1}),
                                       vertex({1, 1, 1}),       vertex({0, 2, 1})};
    Reconstructor r;
    const auto m = single(r, {batch(GL_TRIANGLES, tris), batch(GL_TRIANGLE_STRIP, strip)});
    ASSERT_TRUE(m);
    EXPECT_EQ(m->stats.triangles, 7u);
    EXPECT_EQ(m->stats.nonFiniteTriangles, 3u);
    EXPECT_EQ(m->faceCount(), 4u);
    for (uint32_t v = 0; v < m->vertexCount(); ++v) {
        const glm::vec3 p = m->position(v);
        EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    }
}

TEST(Reconstruct, DegenerateTrianglesAreDroppedAndCounted)
{
    const std::vector<Vertex> tris = {
        vertex({0, 0, 0}), vertex({1, 0, 0}), vertex({0, 1, 0}),  // kept
        vertex({0, 0, 0}), vertex({1, 0, 0}), vertex({1, 0, 0}),  // repeated vertex
        vertex({0, 0, 0}), vertex({1, 0, 0}), vertex({2, 0, 0}),  // collinear: zero area
        vertex({0, 0, 0}), vertex({1, 0, 0}), vertex({1, 1e-9f, 0})}; // welds onto (1,0,0)
    Reconstructor r;
    const auto m = single(r, {batch(GL_TRIANGLES, tris)});
    ASSERT_TRUE(m);
    EXPECT_EQ(m->stats.degenerateTriangles, 3u);
    EXPECT_EQ(m->faceCount(), 1u);
    EXPECT_EQ(m->vertexCount(), 3u); // vertices of dropped triangles only are not in the mesh
}

TEST(Reconstruct, EmptyFramesAndObjectsWithoutFaces)
{
    Reconstructor r;
    EXPECT_TRUE(r.build({}).empty());
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const auto m = single(r, {batch(GL_TRIANGLES, {vertex({nan, 0, 0}), vertex({1, 0, 0}),
                                                   vertex({0, 1, 0}), vertex({2, 2, 2})}),
                              batch(GL_QUAD_STRIP, {}), batch(GL_LINES, {vertex({0, 0, 0})})});
    ASSERT_TRUE(m);
    EXPECT_EQ(m->faceCount(), 0u);
    EXPECT_EQ(m->vertexCount(), 0u);
    EXPECT_EQ(m->edgeCount(), 0u);
    EXPECT_EQ(m->stats.nonFiniteTriangles, 1u);
    EXPECT_EQ(m->stats.incompleteVertices, 2u); // the fourth triangle vertex, the line vertex
    EXPECT_TRUE(silhouetteEdges(*m, glm::vec3(1.0f)).empty());
}

// Silhouette edges as vertex adjacency; checks one closed loop through all of them.
void expectOneClosedLoop(const ObjectMesh& m, const std::vector<EdgeIndex>& edges)
{
    ASSERT_FALSE(edges.empty());
    std::map<uint32_t, std::vector<EdgeIndex>> around;
    for (EdgeIndex e : edges) {
        around[m.edges[e].v0].push_back(e);
        around[m.edges[e].v1].push_back(e);
    }
    for (const auto& [v, list] : around) ASSERT_EQ(list.size(), 2u) << "vertex " << v;
    std::set<EdgeIndex> visited;
    EdgeIndex e = edges[0];
    uint32_t v = m.edges[e].v1;
    while (visited.insert(e).second) {
        const std::vector<EdgeIndex>& next = around[v];
        e = next[0] == e ? next[1] : next[0];
        v = m.edges[e].v0 == v ? m.edges[e].v1 : m.edges[e].v0;
    }
    EXPECT_EQ(e, edges[0]);
    EXPECT_EQ(visited.size(), edges.size()) << "more than one loop";
}

TEST(Silhouette, SphereFromOutsideIsOneClosedLoop)
{
    Reconstructor r;
    const auto m = single(r, sphere(32, 16));
    ASSERT_TRUE(m);
    for (const glm::vec3 eye : {glm::vec3(3.1f, 1.7f, 2.3f), glm::vec3(-0.3f, 4.2f, -1.1f),
                                glm::vec3(0.2f, 0.1f, -9.0f)}) {
        const std::vector<EdgeIndex> edges = silhouetteEdges(*m, eye);
        SCOPED_TRACE(edges.size());
        expectOneClosedLoop(*m, edges);
        // The loop separates front from back: every silhouette edge's faces disagree.
        for (EdgeIndex e : edges) {
            const EdgeInfo& info = m->edges[e];
            const glm::vec3 mid = 0.5f * (m->position(info.v0) + m->position(info.v1));
            const float d0 = glm::dot(m->faceNormal(info.f0), eye - mid);
            const float d1 = glm::dot(m->faceNormal(info.f1), eye - mid);
            EXPECT_LT(d0 * d1, 0.0f);
        }
    }
    // The eye through the modelview: an identity-rotation camera 5 units along +z.
    const glm::mat4 view = glm::mat4(1.0f) + glm::mat4(0.0f, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
                                                       0, 0, -5, 0);
    const glm::vec3 eye = eyeInObjectSpace(view);
    EXPECT_NEAR(eye.z, 5.0f, 1e-5f);
    expectOneClosedLoop(*m, silhouetteEdges(*m, eye));
}

TEST(Silhouette, BorderEdgesCountWhenTheirFaceFacesTheEye)
{
    Reconstructor r;
    const auto m = single(r, {batch(GL_TRIANGLES, {vertex({0, 0, 0}), vertex({1, 0, 0}),
                                                   vertex({0, 1, 0})})});
    ASSERT_TRUE(m);
    EXPECT_EQ(m->borderEdgeCount(), 3u);
    EXPECT_EQ(silhouetteEdges(*m, glm::vec3(0.2f, 0.2f, 3.0f)).size(), 3u);
    EXPECT_TRUE(silhouetteEdges(*m, glm::vec3(0.2f, 0.2f, -3.0f)).empty());
    EXPECT_FALSE(isSilhouette(*m, 99, glm::vec3(0.0f, 0.0f, 1.0f)));
}

TEST(Silhouette, CubeSeenAlongADiagonalHasSixEdges)
{
    Reconstructor r;
    const auto m = single(r, cube());
    ASSERT_TRUE(m);
    const std::vector<EdgeIndex> edges = silhouetteEdges(*m, glm::vec3(5.0f, 4.0f, 3.0f));
    EXPECT_EQ(edges.size(), 6u);
    expectOneClosedLoop(*m, edges);
}

TEST(Cache, UnchangedBatchesAreAHit)
{
    Reconstructor r;
    const std::vector<Batch> frame = sphere(16, 8);
    const auto first = single(r, frame);
    const auto second = single(r, frame);
    EXPECT_EQ(first, second);
    const CacheStats stats = r.cacheStats();
    EXPECT_EQ(stats.rebuilds, 1u);
    EXPECT_EQ(stats.hits, 1u);
    EXPECT_EQ(stats.updates, 0u);
    EXPECT_EQ(stats.entries, 1u);
    EXPECT_GT(stats.bytes, 0u);
}

TEST(Cache, MissingContentHashIsComputed)
{
    std::vector<Batch> frame = cube();
    for (Batch& b : frame) b.contentHash = 0;
    Reconstructor r;
    single(r, frame);
    single(r, frame);
    EXPECT_EQ(r.cacheStats().hits, 1u);
    EXPECT_EQ(r.cacheStats().rebuilds, 1u);
}

TEST(Cache, MovedPositionsWithSameTopologyAreAnUpdate)
{
    Reconstructor r;
    std::vector<Batch> frame = sphere(16, 8);
    std::vector<FrameObject> objects;
    r.build(frame, objects);
    ASSERT_EQ(objects.size(), 1u);
    const ObjectMesh* before = objects[0].mesh.get();
    const uint32_t vertices = before->vertexCount(), edges = before->edgeCount();
    const uint32_t version = before->geometryVersion;

    // Squash the sphere: every vertex moves, the weld map stays.
    for (Batch& b : frame) {
        for (Vertex& v : b.vertices) v.position *= glm::vec3(1.0f, 1.0f, 0.5f);
    }
    rehash(frame);
    r.build(frame, objects); // releases last frame's pointer first: updated in place
    ASSERT_EQ(objects.size(), 1u);
    const ObjectMesh& after = *objects[0].mesh;
    EXPECT_EQ(&after, before);
    EXPECT_EQ(after.geometryVersion, version + 1);
    EXPECT_EQ(after.vertexCount(), vertices);
    EXPECT_EQ(after.edgeCount(), edges);
    EXPECT_TRUE(after.closed());
    float maxZ = 0.0f;
    for (uint32_t v = 0; v < after.vertexCount(); ++v)
        maxZ = std::max(maxZ, std::abs(after.position(v).z));
    EXPECT_FLOAT_EQ(maxZ, 0.5f);
    CacheStats stats = r.cacheStats();
    EXPECT_EQ(stats.updates, 1u);
    EXPECT_EQ(stats.rebuilds, 1u);
    EXPECT_EQ(stats.hits, 0u);
    EXPECT_EQ(stats.entries, 1u);

    // Someone holds the mesh: the update goes to a copy and theirs stays as it was.
    const std::shared_ptr<const ObjectMesh> held = objects[0].mesh;
    for (Batch& b : frame) {
        for (Vertex& v : b.vertices) v.position.x += 0.25f;
    }
    rehash(frame);
    r.build(frame, objects);
    ASSERT_EQ(objects.size(), 1u);
    EXPECT_NE(objects[0].mesh, held);
    EXPECT_NEAR(held->position(0).x, frame[0].vertices[0].position.x - 0.25f, 1e-6f);
    EXPECT_NEAR(objects[0].mesh->position(0).x, frame[0].vertices[0].position.x, 1e-6f);
    stats = r.cacheStats();
    EXPECT_EQ(stats.updates, 2u);
    EXPECT_EQ(stats.rebuilds, 1u);

    // The previous content is gone from the cache (the entry now shows the new one).
    r.build(frame, objects);
    EXPECT_EQ(r.cacheStats().hits, 1u);
}

TEST(Cache, ChangedTopologyIsARebuild)
{
    Reconstructor r;
    single(r, sphere(16, 8));
    single(r, sphere(16, 9)); // other vertex counts
    EXPECT_EQ(r.cacheStats().rebuilds, 2u);
    EXPECT_EQ(r.cacheStats().updates, 0u);

    // Same counts, but one quad moves off the cube: the weld map changes.
    std::vector<Batch> frame = cube();
    single(r, frame);
    for (Vertex& v : frame[2].vertices) v.position.y += 0.5f;
    rehash(frame);
    const auto m = single(r, frame);
    ASSERT_TRUE(m);
    EXPECT_EQ(r.cacheStats().rebuilds, 4u);
    EXPECT_EQ(r.cacheStats().updates, 0u);
    EXPECT_FALSE(m->closed());
}

TEST(Cache, LeastRecentlyUsedIsEvictedOverBudget)
{
    const std::vector<Batch> a = sphere(16, 8), b = torus(16, 8), c = sphere(20, 10);
    Reconstructor probe;
    single(probe, a);
    const size_t bytesA = probe.cacheStats().bytes;
    single(probe, b);
    const size_t bytesB = probe.cacheStats().bytes - bytesA;
    single(probe, c);
    const size_t bytesC = probe.cacheStats().bytes - bytesA - bytesB;
    ASSERT_GT(bytesA, 0u);
    ASSERT_GT(bytesB, 0u);
    ASSERT_GT(bytesC, 0u);

    // Room for a with b or with c, not for all three.
    Reconstructor r({}, bytesA + std::max(bytesB, bytesC));
    single(r, a);
    single(r, b);
    single(r, a); // a is now the most recently used
    EXPECT_EQ(r.cacheStats().hits, 1u);
    single(r, c); // evicts b, the least recently used
    EXPECT_EQ(r.cacheStats().evictions, 1u);
    EXPECT_EQ(r.cacheStats().entries, 2u);
    EXPECT_LE(r.cacheStats().bytes, r.cacheStats().budgetBytes);
    single(r, a);
    EXPECT_EQ(r.cacheStats().hits, 2u);
    const uint64_t rebuilds = r.cacheStats().rebuilds;
    single(r, b);
    EXPECT_EQ(r.cacheStats().rebuilds, rebuilds + 1);

    // An object larger than the whole budget is returned but not kept.
    Reconstructor tiny({}, 1024);
    EXPECT_TRUE(single(tiny, a));
    EXPECT_EQ(tiny.cacheStats().entries, 0u);
    EXPECT_EQ(tiny.cacheStats().bytes, 0u);
}

class Export : public ::testing::Test {
protected:
    void SetUp() override
    {
        mDir = std::filesystem::path(::testing::TempDir()) /
               ("nprgl_reconstruct_" + std::to_string(::getpid()));
        std::filesystem::create_directories(mDir);
        mMesh = single(mReconstructor, cube());
    }
    void TearDown() override { std::filesystem::remove_all(mDir); }

    using PlainMesh = OpenMesh::TriMesh_ArrayKernelT<>;
    static bool readBack(const std::string& path, PlainMesh& mesh)
    {
        return OpenMesh::IO::read_mesh(mesh, path);
    }

    std::filesystem::path mDir;
    Reconstructor mReconstructor;
    std::shared_ptr<const ObjectMesh> mMesh;
};

TEST_F(Export, CubeReadsBackInEveryFormat)
{
    ASSERT_TRUE(mMesh);
    for (const char* name : {"cube.obj", "cube.ply", "cube.off", "CUBE.OBJ"}) {
        const std::string path = (mDir / name).string();
        std::string error;
        ASSERT_TRUE(exportMeshes(path, {{mMesh, glm::mat4(1.0f)}}, error)) << error;
        PlainMesh back;
        ASSERT_TRUE(readBack(path, back)) << path;
        EXPECT_EQ(back.n_vertices(), 8u) << name;
        EXPECT_EQ(back.n_faces(), 12u) << name;
    }
}

TEST_F(Export, ObjGroupsObjectsAndAppliesTransforms)
{
    ASSERT_TRUE(mMesh);
    glm::mat4 moved(1.0f);
    moved[3] = glm::vec4(10.0f, 0.0f, 0.0f, 1.0f);
    const std::string path = (mDir / "two.obj").string();
    std::string error;
    ASSERT_TRUE(exportMeshes(path, {{mMesh, glm::mat4(1.0f)}, {mMesh, moved}}, error)) << error;
    std::ifstream in(path);
    std::string line;
    std::vector<std::string> groups;
    while (std::getline(in, line)) {
        if (line.rfind("g ", 0) == 0) groups.push_back(line);
    }
    EXPECT_EQ(groups, (std::vector<std::string>{"g object_0", "g object_1"}));
    PlainMesh back;
    ASSERT_TRUE(readBack(path, back));
    EXPECT_EQ(back.n_vertices(), 16u);
    EXPECT_EQ(back.n_faces(), 24u);
    float maxX = -1e9f;
    for (auto vh : back.vertices()) maxX = std::max(maxX, back.point(vh)[0]);
    EXPECT_FLOAT_EQ(maxX, 11.0f);

    // PLY merges both objects, transformed.
    const std::string ply = (mDir / "two.ply").string();
    ASSERT_TRUE(exportMeshes(ply, {{mMesh, glm::mat4(1.0f)}, {mMesh, moved}}, error)) << error;
    PlainMesh plyBack;
    ASSERT_TRUE(readBack(ply, plyBack));
    EXPECT_EQ(plyBack.n_vertices(), 16u);
    EXPECT_EQ(plyBack.n_faces(), 24u);
}

TEST_F(Export, ErrorsAreReportedNotThrown)
{
    std::string error;
    EXPECT_FALSE(exportMeshes((mDir / "cube.stl2").string(), {{mMesh, glm::mat4(1.0f)}}, error));
    EXPECT_NE(error.find("unknown mesh format"), std::string::npos) << error;
    error.clear();
    EXPECT_FALSE(exportMeshes((mDir / "missing" / "cube.obj").string(),
                              {{mMesh, glm::mat4(1.0f)}}, error));
    EXPECT_FALSE(error.empty());
    error.clear();
    EXPECT_FALSE(exportMeshes((mDir / "missing" / "cube.ply").string(),
                              {{mMesh, glm::mat4(1.0f)}}, error));
    EXPECT_FALSE(error.empty());
}

} // namespace
} // namespace nprgl::reconstruct
