// Geometric strokes (thesis 4.4): chaining, visibility, stroke building and rendering.

#include "reconstruct/Reconstructor.h"
#include "reconstruct/Silhouette.h"
#include "styles/MeshBuffers.h"
#include "styles/ShaderProgram.h"
#include "styles/strokes/ChainExtractor.h"
#include "styles/strokes/ChainProjector.h"
#include "styles/strokes/DepthVisibility.h"
#include "styles/strokes/QueryVisibility.h"
#include "styles/strokes/StrokeBuilder.h"
#include "styles/strokes/StrokeSimplifier.h"
#include "styles/strokes/StrokeTexture.h"
#include "tests/support/Process.h"
#include "tests/support/StyleHarness.h"

#include <gtest/gtest.h>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <map>
#include <sys/stat.h>

using namespace nprgl;
using namespace nprgl::test;
using namespace nprgl::styles::strokes;
using reconstruct::FrameObject;

namespace {

constexpr int kSize = 256;

glm::mat4 perspective() { return glm::perspective(glm::radians(40.0f), 1.0f, 1.0f, 20.0f); }

std::vector<FrameObject> meshes(reconstruct::Reconstructor& r,
                                const std::vector<reconstruct::Batch>& batches)
{
    return r.build(batches);
}

reconstruct::Batch torusBatch(const glm::mat4& modelview, float major, float minor, int rings,
                              int sides)
{
    reconstruct::Batch b;
    b.mode = GL_TRIANGLES;
    b.modelview = modelview;
    b.materialId = 1;
    const float pi = glm::pi<float>();
    auto point = [&](int i, int j) {
        const float theta = 2.0f * pi * float(i % rings) / float(rings);
        const float phi = 2.0f * pi * float(j % sides) / float(sides);
        const glm::vec3 n(std::cos(phi) * std::cos(theta), std::sin(phi),
                          std::cos(phi) * std::sin(theta));
        reconstruct::Vertex v{};
        v.position = glm::vec3(major * std::cos(theta), 0.0f, major * std::sin(theta)) + minor * n;
        v.normal = n;
        v.color = glm::vec4(0.9f, 0.75f, 0.4f, 1.0f);
        v.hasNormal = true;
        return v;
    };
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < sides; ++j) {
            const reconstruct::Vertex a = point(i, j), c = point(i + 1, j),
                                      d = point(i + 1, j + 1), e = point(i, j + 1);
            b.vertices.insert(b.vertices.end(), {a, e, d, a, d, c});
        }
    }
    return b;
}

// Every chain is connected (each segment's edge joins its two vertices); returns how often
// each edge occurs.
std::map<uint32_t, int> checkChains(const reconstruct::ObjectMesh& mesh, const EdgeChains& c)
{
    std::map<uint32_t, int> uses;
    for (uint32_t k = 0; k < c.chainCount(); ++k) {
        const uint32_t begin = c.vertexStart[k], end = c.vertexStart[k + 1];
        EXPECT_GE(end - begin, 2u);
        if (c.closed[k]) {
            EXPECT_EQ(c.vertices[begin], c.vertices[end - 1]);
        }
        for (uint32_t i = begin; i + 1 < end; ++i) {
            const uint32_t e = c.edges[c.firstEdge(k) + (i - begin)];
            const auto& info = mesh.edges[e];
            const uint32_t a = c.vertices[i], b = c.vertices[i + 1];
            EXPECT_TRUE((info.v0 == a && info.v1 == b) || (info.v0 == b && info.v1 == a));
            ++uses[e];
        }
    }
    EXPECT_EQ(c.edges.size(), c.vertices.size() - c.chainCount());
    return uses;
}

// Interior silhouette edges by eq. 4.1 (Silhouette.h also counts front-facing borders).
std::vector<uint32_t> interiorSilhouettes(const reconstruct::ObjectMesh& mesh, glm::vec3 eye)
{
    std::vector<uint32_t> out;
    for (uint32_t e : reconstruct::silhouetteEdges(mesh, eye))
        if (mesh.edges[e].f0 != reconstruct::kNoIndex && mesh.edges[e].f1 != reconstruct::kNoIndex)
            out.push_back(e);
    return out;
}

void expectEachSilhouetteOnce(const reconstruct::ObjectMesh& mesh, glm::vec3 eye,
                              const EdgeChains& chains)
{
    const auto uses = checkChains(mesh, chains);
    const auto expected = interiorSilhouettes(mesh, eye);
    ASSERT_FALSE(expected.empty());
    EXPECT_EQ(uses.size(), expected.size());
    for (uint32_t e : expected) {
        auto it = uses.find(e);
        ASSERT_NE(it, uses.end()) << "silhouette edge " << e << " in no chain";
        EXPECT_EQ(it->second, 1) << "edge " << e;
    }
}

} // namespace

TEST(StrokeChains, SphereSilhouetteIsOneClosedLoop)
{
    reconstruct::Reconstructor r;
    const glm::mat4 mv = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -6)),
                                     0.3f, glm::vec3(1, 0.2f, 0));
    auto objects = meshes(r, {sphereBatch(mv, 1.5f, 48, 24, glm::vec4(1))});
    ASSERT_EQ(objects.size(), 1u);
    const auto& mesh = *objects[0].mesh;
    const glm::vec3 eye = reconstruct::eyeInObjectSpace(mv);
    ChainExtractor extractor;
    EdgeChains chains;
    extractor.extract(mesh, eye, {}, chains);
    ASSERT_EQ(chains.chainCount(), 1u);
    EXPECT_TRUE(chains.closed[0]);
    EXPECT_EQ(extractor.silhouetteCount(), chains.edges.size());
    expectEachSilhouetteOnce(mesh, eye, chains);
}

TEST(StrokeChains, CubeCornerOnIsOneLoopOfSixEdges)
{
    reconstruct::Reconstructor r;
    // Rotate the (1,1,1) diagonal onto +z, towards the eye.
    const glm::vec3 diagonal = glm::normalize(glm::vec3(1.0f));
    const glm::vec3 axis = glm::normalize(glm::cross(diagonal, glm::vec3(0, 0, 1)));
    const float angle = std::acos(glm::dot(diagonal, glm::vec3(0, 0, 1)));
    const glm::mat4 mv =
        glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -6)), angle, axis);
    auto objects = meshes(r, {boxBatch(mv, glm::vec3(1.0f), glm::vec4(1))});
    const auto& mesh = *objects[0].mesh;
    const glm::vec3 eye = reconstruct::eyeInObjectSpace(mv);
    ChainExtractor extractor;
    EdgeChains chains;
    extractor.extract(mesh, eye, {}, chains);
    ASSERT_EQ(chains.chainCount(), 1u);
    EXPECT_TRUE(chains.closed[0]);
    EXPECT_EQ(chains.edges.size(), 6u);
    expectEachSilhouetteOnce(mesh, eye, chains);

    // With creases, the three front edges join too, each in exactly one chain.
    ChainExtractor::Options withCreases;
    withCreases.creases = true;
    extractor.extract(mesh, eye, withCreases, chains);
    const auto uses = checkChains(mesh, chains);
    EXPECT_EQ(uses.size(), 12u); // every cube edge is a crease
    for (const auto& [edge, count] : uses) EXPECT_EQ(count, 1) << edge;
    // The silhouette loop survives intact as the first chain.
    EXPECT_TRUE(chains.closed[0]);
    EXPECT_EQ(chains.vertexStart[1] - chains.vertexStart[0], 7u);
}

TEST(StrokeChains, TorusFromAboveHasTwoLoops)
{
    reconstruct::Reconstructor r;
    // Looking down the torus axis (tilted a little so nothing is exactly tangent).
    const glm::mat4 mv = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -8)),
                                     glm::radians(83.0f), glm::vec3(1, 0, 0));
    auto objects = meshes(r, {torusBatch(mv, 2.0f, 0.6f, 64, 32)});
    const auto& mesh = *objects[0].mesh;
    ASSERT_EQ(mesh.eulerCharacteristic(), 0);
    const glm::vec3 eye = reconstruct::eyeInObjectSpace(mv);
    ChainExtractor extractor;
    EdgeChains chains;
    extractor.extract(mesh, eye, {}, chains);
    EXPECT_EQ(chains.chainCount(), 2u);
    for (uint32_t c = 0; c < chains.chainCount(); ++c) EXPECT_TRUE(chains.closed[c]);
    expectEachSilhouetteOnce(mesh, eye, chains);
}

TEST(StrokeChains, EveryEdgeOnceAndDeterministicOnHardShapes)
{
    reconstruct::Reconstructor r;
    // An oblique torus (folds, branching) and a coarse bumpy sphere (zig-zag silhouettes).
    const glm::mat4 mvTorus = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -7)),
                                          glm::radians(25.0f), glm::vec3(1, 0.3f, 0));
    reconstruct::Batch bumpy = sphereBatch(
        glm::translate(glm::mat4(1.0f), glm::vec3(0.1f, 0, -5)), 1.2f, 13, 9, glm::vec4(1), 2);
    for (auto& v : bumpy.vertices) {
        const float k = 1.0f + 0.15f * std::sin(7.0f * v.position.x + 5.0f * v.position.y) *
                                   std::cos(3.0f * v.position.z);
        v.position *= k;
    }
    for (const reconstruct::Batch& batch : {torusBatch(mvTorus, 2.0f, 0.7f, 40, 18), bumpy}) {
        auto objects = meshes(r, {batch});
        const auto& mesh = *objects[0].mesh;
        for (int view = 0; view < 12; ++view) {
            const glm::mat4 mv = glm::rotate(batch.modelview, 0.5f * float(view),
                                             glm::vec3(0.2f, 1, 0.1f));
            const glm::vec3 eye = reconstruct::eyeInObjectSpace(mv);
            ChainExtractor a, b;
            EdgeChains first, second, third;
            a.extract(mesh, eye, {}, first);
            b.extract(mesh, eye, {}, second);
            a.extract(mesh, eye, {}, third);
            expectEachSilhouetteOnce(mesh, eye, first);
            EXPECT_EQ(first.vertices, second.vertices);
            EXPECT_EQ(first.edges, second.edges);
            EXPECT_EQ(first.vertices, third.vertices);
            EXPECT_EQ(first.closed, second.closed);
        }
    }
}

namespace {

// A straight or bent polyline on screen for the stroke builder; depth and w are constant.
Polylines screenPath(const std::vector<glm::vec2>& points, bool closed = false,
                     const std::vector<uint8_t>& states = {})
{
    Polylines lines;
    for (size_t i = 0; i < points.size(); ++i) {
        ChainPoint p;
        p.object = glm::vec3(points[i], 0.0f);
        p.window = glm::vec3(points[i], 0.5f);
        p.va = p.vb = uint32_t(i);
        const uint8_t state = i < states.size() ? states[i] : uint8_t(kVisible);
        lines.addPoint(p, uint32_t(i), i + 1 < points.size() ? state : uint8_t(kUnknown));
    }
    lines.endPolyline(closed);
    return lines;
}

float strokeLength(const Polylines& s, uint32_t k)
{
    float length = 0.0f;
    for (uint32_t i = s.start[k]; i + 1 < s.start[k + 1]; ++i)
        length += glm::distance(glm::vec2(s.points[i].window), glm::vec2(s.points[i + 1].window));
    return length;
}

} // namespace

TEST(StrokeBuilding, SplitsAtSharpAnglesFirst)
{
    StrokeBuilder builder;
    Polylines strokes;
    // An open square path: three right-angle turns.
    Polylines square = screenPath({{0, 0}, {100, 0}, {100, 100}, {0, 100}, {0, 0}});
    StrokeBuilder::Options options;
    options.maxAngle = 60.0f;
    builder.build(square, options, strokes);
    EXPECT_EQ(strokes.count(), 4u);
    options.maxAngle = 120.0f;
    builder.build(square, options, strokes);
    EXPECT_EQ(strokes.count(), 1u);
    // Closed, the seam corner is a break too and no stroke ends at the seam alone.
    Polylines loop = screenPath({{0, 0}, {100, 0}, {100, 100}, {0, 100}, {0, 0}}, true);
    options.maxAngle = 60.0f;
    builder.build(loop, options, strokes);
    EXPECT_EQ(strokes.count(), 4u);
    for (uint32_t k = 0; k < strokes.count(); ++k) EXPECT_NEAR(strokeLength(strokes, k), 100, 1e-3);
    // A smooth closed loop stays one closed stroke.
    std::vector<glm::vec2> circle;
    for (int i = 0; i <= 32; ++i) {
        const float a = 2.0f * glm::pi<float>() * float(i % 32) / 32.0f;
        circle.push_back(glm::vec2(50.0f * std::cos(a), 50.0f * std::sin(a)));
    }
    builder.build(screenPath(circle, true), options, strokes);
    ASSERT_EQ(strokes.count(), 1u);
    EXPECT_TRUE(strokes.closed[0]);
    // The angle rule wins over the length rule: a 60 px limit on 100 px sides still breaks
    // at every corner, and cuts each side into balanced halves.
    options.maxLength = 60.0f;
    builder.build(screenPath({{0, 0}, {50, 0}, {100, 0}, {100, 50}, {100, 100}}), options,
                  strokes);
    ASSERT_EQ(strokes.count(), 4u);
    for (uint32_t k = 0; k < strokes.count(); ++k) EXPECT_NEAR(strokeLength(strokes, k), 50, 1e-3);
}

TEST(StrokeBuilding, SplitsAtMaxLengthAndSegmentsAndHiddenParts)
{
    StrokeBuilder builder;
    Polylines strokes;
    std::vector<glm::vec2> line;
    for (int i = 0; i <= 10; ++i) line.push_back(glm::vec2(50.0f * float(i), 0.0f));
    StrokeBuilder::Options options;
    options.maxLength = 150.0f;
    builder.build(screenPath(line), options, strokes);
    ASSERT_EQ(strokes.count(), 4u); // 500 px in balanced pieces of <= 150 px
    for (uint32_t k = 0; k < strokes.count(); ++k) {
        EXPECT_LE(strokeLength(strokes, k), 150.0f + 1e-3f);
        EXPECT_GE(strokeLength(strokes, k), 100.0f - 1e-3f);
    }
    options.maxLength = 0.0f;
    options.maxSegments = 3;
    builder.build(screenPath(line), options, strokes);
    ASSERT_EQ(strokes.count(), 4u);
    for (uint32_t k = 0; k < strokes.count(); ++k)
        EXPECT_LE(strokes.start[k + 1] - strokes.start[k] - 1, 3u);
    // Hidden segments are left out and end strokes.
    options.maxSegments = 0;
    std::vector<uint8_t> states(10, kVisible);
    states[3] = states[4] = kHidden;
    states[8] = kHidden;
    builder.build(screenPath(line, false, states), options, strokes);
    ASSERT_EQ(strokes.count(), 3u);
    EXPECT_NEAR(strokeLength(strokes, 0), 150, 1e-3);
    EXPECT_NEAR(strokeLength(strokes, 1), 150, 1e-3);
    EXPECT_NEAR(strokeLength(strokes, 2), 50, 1e-3);
}

// Balanced pieces by length where short segments come before a long one: the first piece
// takes the three short ones, the second the long one, and the pieces left have nothing to
// take. They were given one segment past the run's end (a stroke point read past the
// polyline, with a stray mesh edge index: the pencil crashes in etr and openarena).
TEST(StrokeBuilding, PiecesNeverReachPastTheirRun)
{
    StrokeBuilder builder;
    Polylines strokes;
    StrokeBuilder::Options options;
    options.maxAngle = 180.0f;
    options.maxLength = 30.0f; // 103 px: four pieces, capped at the four segments
    options.minLength = 0.0f;
    const Polylines line = screenPath({{0, 0}, {1, 0}, {2, 0}, {3, 0}, {103, 0}});
    builder.build(line, options, strokes);
    ASSERT_EQ(strokes.count(), 2u);
    uint32_t segments = 0;
    for (uint32_t k = 0; k < strokes.count(); ++k) {
        segments += strokes.start[k + 1] - strokes.start[k] - 1;
        for (uint32_t i = strokes.start[k]; i + 1 < strokes.start[k + 1]; ++i) {
            EXPECT_LT(strokes.edge[i], 4u) << "a segment from outside the polyline";
        }
    }
    EXPECT_EQ(segments, 4u);
    EXPECT_NEAR(strokeLength(strokes, 0) + strokeLength(strokes, 1), 103.0f, 1e-3);
}

TEST(StrokeSimplification, MergesOnlyExactlyCollinearVisibleSegments)
{
    // Four pieces of one straight edge (as refinement leaves them), then a slight turn.
    Polylines lines = screenPath({{0, 0}, {10, 0}, {20, 0}, {30, 0}, {40, 0}, {50, 0.5f}});
    for (uint32_t i = 0; i < 4; ++i) lines.edge[i] = 7;
    lines.state[2] = kHidden;
    StrokeSimplifier simplifier;
    EXPECT_EQ(simplifier.simplify(lines), 1u); // only (0-10, 10-20): both visible
    EXPECT_EQ(lines.points.size(), 5u);
    EXPECT_EQ(lines.start[1], 5u);
    for (uint32_t i = 0; i < 4; ++i) lines.state[i] = kVisible;
    simplifier.simplify(lines);
    EXPECT_EQ(lines.points.size(), 3u); // the slight turn at (40, 0) stays
}

namespace {

const char* const kDepthVertex = StyleHarness::depthVertexShader();
const char* const kDepthFragment = StyleHarness::depthFragmentShader();

// The state a method gave to the point at `fraction` along mesh edge `edge`.
uint8_t stateAt(const reconstruct::ObjectMesh& mesh, const Polylines& lines, uint32_t edge,
                float fraction)
{
    const auto& info = mesh.edges[edge];
    for (uint32_t p = 0; p < lines.count(); ++p) {
        for (uint32_t i = lines.start[p]; i + 1 < lines.start[p + 1]; ++i) {
            if (lines.edge[i] != edge) continue;
            float a = edgeFraction(lines.points[i], info.v0, info.v1);
            float b = edgeFraction(lines.points[i + 1], info.v0, info.v1);
            if (a > b) std::swap(a, b);
            if (fraction >= a && fraction <= b) return lines.state[i];
        }
    }
    return kUnknown;
}

} // namespace

TEST(StrokeVisibility, QueryAndDepthAgreeOnHalfHiddenSphere)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const styles::GlFunctions& gl = harness.gl();
    // A near sphere hiding part of a far one.
    const glm::mat4 nearMv = glm::translate(glm::mat4(1.0f), glm::vec3(-0.7f, 0.1f, -5.0f));
    const glm::mat4 farMv = glm::translate(glm::mat4(1.0f), glm::vec3(0.8f, 0.0f, -7.5f));
    const glm::vec3 nearCentre(-0.7f, 0.1f, -5.0f);
    const float nearRadius = 1.0f;
    auto scene = harness.makeScene({sphereBatch(nearMv, nearRadius, 48, 24, glm::vec4(1)),
                                    sphereBatch(farMv, 1.6f, 48, 24, glm::vec4(1), 2)},
                                   perspective());
    ASSERT_EQ(scene.objects.size(), 2u);

    // The compositor's depth pre-pass.
    GLuint vao = 0;
    gl.GenVertexArrays(1, &vao);
    gl.BindVertexArray(vao);
    gl.Viewport(0, 0, kSize, kSize);
    gl.ClearDepth(1.0);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LESS);
    styles::ShaderProgram depth;
    std::string error;
    ASSERT_TRUE(depth.build(gl, kDepthVertex, kDepthFragment, error)) << error;
    gl.UseProgram(depth.id());
    styles::MeshBuffers buffers;
    for (const auto& o : scene.objects) {
        const glm::mat4 mvp = o.projection * o.modelview;
        gl.UniformMatrix4fv(depth.uniform(gl, "mvp"), 1, GL_FALSE, glm::value_ptr(mvp));
        buffers.draw(gl, *o.mesh);
    }
    std::vector<float> depthBuffer(size_t(kSize) * kSize);
    gl.ReadPixels(0, 0, kSize, kSize, GL_DEPTH_COMPONENT, GL_FLOAT, depthBuffer.data());
    const DepthImage image{depthBuffer.data(), 0, 0, kSize, kSize};

    const auto& far = scene.objects[1];
    const auto& mesh = *far.mesh;
    ChainExtractor extractor;
    EdgeChains chains;
    extractor.extract(mesh, reconstruct::eyeInObjectSpace(far.modelview), {}, chains);
    ChainProjector projector;
    Polylines original, byDepth, byQuery;
    projector.project(mesh, chains, far.modelview, far.projection, scene.viewport, 0.01f,
                      original);
    byDepth = byQuery = original;
    DepthVisibility depthVisibility;
    depthVisibility.classify(mesh, image, {}, byDepth);
    QueryVisibility queryVisibility;
    ASSERT_TRUE(queryVisibility.init(gl, error)) << error;
    gl.BindVertexArray(vao);
    queryVisibility.classify(gl, mesh, scene.viewport, {}, byQuery);
    EXPECT_GT(queryVisibility.queryCount(), 0u);

    // Compare both, and the truth (is the far silhouette point behind the near sphere?),
    // by screen length.
    float total = 0, agree = 0, depthRight = 0, queryRight = 0, hiddenLength = 0;
    for (uint32_t p = 0; p < original.count(); ++p) {
        for (uint32_t i = original.start[p]; i + 1 < original.start[p + 1]; ++i) {
            const uint32_t edge = original.edge[i];
            const auto& info = mesh.edges[edge];
            const ChainPoint& a = original.points[i];
            const ChainPoint& b = original.points[i + 1];
            const float length = glm::distance(glm::vec2(a.window), glm::vec2(b.window));
            constexpr int kSamples = 8;
            for (int k = 0; k < kSamples; ++k) {
                const float s = (float(k) + 0.5f) / kSamples;
                const ChainPoint q = splitPoint(a, b, s, info.v0, info.v1);
                const float f = edgeFraction(q, info.v0, info.v1);
                const uint8_t d = stateAt(mesh, byDepth, edge, f);
                const uint8_t qs = stateAt(mesh, byQuery, edge, f);
                // Truth: the ray from the eye to the point meets the near sphere first.
                const glm::vec3 point = glm::vec3(far.modelview * glm::vec4(q.object, 1.0f));
                const glm::vec3 dir = glm::normalize(point);
                const float tc = glm::dot(nearCentre, dir);
                const float miss2 = glm::dot(nearCentre, nearCentre) - tc * tc;
                const bool hidden = tc > 0 && miss2 < nearRadius * nearRadius &&
                                    tc < glm::length(point);
                const float w = length / kSamples;
                total += w;
                hiddenLength += hidden ? w : 0.0f;
                agree += d == qs ? w : 0.0f;
                depthRight += (d == (hidden ? kHidden : kVisible)) ? w : 0.0f;
                queryRight += (qs == (hidden ? kHidden : kVisible)) ? w : 0.0f;
            }
        }
    }
    ASSERT_GT(total, 100.0f);
    // The scene really hides a good part of the far silhouette.
    EXPECT_GT(hiddenLength / total, 0.2f);
    EXPECT_LT(hiddenLength / total, 0.8f);
    EXPECT_GE(agree / total, 0.9f);
    EXPECT_GE(depthRight / total, 0.9f);
    EXPECT_GE(queryRight / total, 0.9f);
    std::printf("far silhouette %.0f px (%zu segments), hidden %.0f%%; depth right %.1f%%, "
                "query right %.1f%%, agree %.1f%% (%u queries)\n",
                total, original.points.size() - original.count(), 100 * hiddenLength / total,
                100 * depthRight / total, 100 * queryRight / total, 100 * agree / total,
                queryVisibility.queryCount());
    queryVisibility.destroy(gl);
    buffers.destroy(gl);
    depth.destroy(gl);
    gl.DeleteVertexArrays(1, &vao);
}

namespace {

// Dark pixels (ink) on a white background.
bool ink(const PngImage& image, int x, int y)
{
    const uint8_t* p = &image.rgba[(size_t(y) * image.width + x) * 4];
    return p[0] + p[1] + p[2] < 3 * 160;
}

// The sphere at (0, 0, -6) with radius 1.5 under perspective(): its outline is a circle
// about the image centre of this radius in pixels.
float silhouetteRadius()
{
    const float d = 6.0f, r = 1.5f;
    const float alpha = std::asin(r / d);
    return std::tan(alpha) / std::tan(glm::radians(20.0f)) * 0.5f * float(kSize);
}

} // namespace

TEST(StrokeRendering, InkHugsTheSphereOutline)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const glm::mat4 mv = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -6)), 0.4f,
                                     glm::vec3(1, 1, 0));
    auto scene = harness.makeScene({sphereBatch(mv, 1.5f, 64, 32, glm::vec4(0.9f, 0.4f, 0.3f, 1))},
                                   perspective());
    const float radius = silhouetteRadius();
    const glm::vec2 centre(0.5f * kSize, 0.5f * kSize);
    for (const char* config :
         {"", "strokes.renderer=sketchy", "strokes.visibility=query",
          "strokes.renderer=sketchy,strokes.visibility=query", "strokes.zbuffer=on",
          "strokes.texture=brush,strokes.max_length=120"}) {
        SCOPED_TRACE(config);
        PngImage image;
        std::string error;
        ASSERT_TRUE(harness.render(scene, "strokes", config, image, error)) << error;
        int far = 0, near = 0;
        for (int y = 0; y < kSize; ++y) {
            for (int x = 0; x < kSize; ++x) {
                if (!ink(image, x, y)) continue;
                const glm::vec2 pixel(x + 0.5f, y + 0.5f);
                const float d = std::abs(glm::distance(pixel, centre) - radius);
                (d > 6.0f ? far : near)++;
            }
        }
        EXPECT_EQ(far, 0);
        EXPECT_GT(near, int(2.0f * glm::pi<float>() * radius)); // a line at least ~1 px wide
        // Ink all round: every direction has ink within 3 px of the circle.
        int covered = 0;
        for (int k = 0; k < 180; ++k) {
            const float a = 2.0f * glm::pi<float>() * float(k) / 180.0f;
            bool found = false;
            for (float dr = -3.0f; dr <= 3.0f && !found; dr += 0.5f) {
                const glm::vec2 p = centre + (radius + dr) * glm::vec2(std::cos(a), std::sin(a));
                found = ink(image, int(p.x), int(p.y));
            }
            covered += found;
        }
        EXPECT_GE(covered, 171) << "outline coverage " << covered << "/180";
        // Same scene, same picture (nothing random per frame), and no GL error left.
        PngImage again;
        ASSERT_TRUE(harness.render(scene, "strokes", config, again, error)) << error;
        EXPECT_EQ(image.rgba, again.rgba);
        EXPECT_EQ(harness.gl().GetError(), GLenum(GL_NO_ERROR));
    }
}

TEST(StrokeRendering, MissingTextureFileFallsBackWithOneError)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const glm::mat4 mv = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -6));
    auto scene = harness.makeScene({sphereBatch(mv, 1.5f, 48, 24, glm::vec4(1))}, perspective());
    PngImage image, procedural;
    std::string error;
    testing::internal::CaptureStderr();
    ASSERT_TRUE(harness.render(scene, "strokes", "strokes.texture_file=/nonexistent/stroke.png",
                               image, error))
        << error;
    const std::string log = testing::internal::GetCapturedStderr();
    EXPECT_NE(log.find("nprgl"), std::string::npos) << log;
    EXPECT_NE(log.find("texture_file"), std::string::npos) << log;
    EXPECT_EQ(log.find("texture_file"), log.rfind("texture_file")) << "more than one error";
    ASSERT_TRUE(harness.render(scene, "strokes", "", procedural, error)) << error;
    EXPECT_EQ(image.rgba, procedural.rgba);

    // A user PNG is used: a solid bar texture draws darker than the pencil.
    PngImage bar;
    bar.width = 64;
    bar.height = 8;
    bar.rgba.assign(size_t(64) * 8 * 4, 0);
    for (size_t i = 0; i < bar.rgba.size(); i += 4) bar.rgba[i + 3] = 255;
    // A directory of this run's own: a PNG the style reads back must be ours.
    const std::string path = freshDir("strokes_bar") + "/solid_bar.png";
    ASSERT_TRUE(bar.write(path, error)) << error;
    PngImage custom;
    ASSERT_TRUE(harness.render(scene, "strokes", "strokes.texture_file=" + path, custom, error))
        << error;
    auto darkness = [](const PngImage& im) {
        double sum = 0;
        for (size_t i = 0; i < im.rgba.size(); i += 4) sum += 255 - im.rgba[i];
        return sum;
    };
    EXPECT_GT(darkness(custom), 1.1 * darkness(procedural));
}

namespace {

// A pixel mask over a kSize x kSize picture.
using Mask = std::vector<uint8_t>;

// Pixels that are not exactly the background colour: the footprint of a style that covers
// the objects and nothing else (toon).
Mask footprint(const PngImage& image, glm::u8vec3 background)
{
    Mask mask(size_t(kSize) * kSize);
    for (size_t i = 0; i < mask.size(); ++i) {
        const uint8_t* p = &image.rgba[i * 4];
        mask[i] = p[0] != background.r || p[1] != background.g || p[2] != background.b;
    }
    return mask;
}

// Pixels at least `amount` (summed over r, g, b) darker than the same pixel of `reference`.
Mask darker(const PngImage& image, const PngImage& reference, int amount = 150)
{
    Mask mask(size_t(kSize) * kSize);
    for (size_t i = 0; i < mask.size(); ++i) {
        int d = 0;
        for (int c = 0; c < 3; ++c) d += reference.rgba[i * 4 + c] - image.rgba[i * 4 + c];
        mask[i] = d >= amount;
    }
    return mask;
}

// Footprint pixels with a 4-neighbour outside it: the outline as the picture shows it.
Mask outline(const Mask& inside)
{
    Mask mask(inside.size());
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            if (!inside[size_t(y) * kSize + x]) continue;
            bool edge = x == 0 || y == 0 || x == kSize - 1 || y == kSize - 1;
            for (auto [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
                const int nx = x + dx, ny = y + dy;
                if (nx >= 0 && ny >= 0 && nx < kSize && ny < kSize)
                    edge = edge || !inside[size_t(ny) * kSize + nx];
            }
            mask[size_t(y) * kSize + x] = edge;
        }
    }
    return mask;
}

// Distance in pixels from every pixel to the nearest pixel of `seeds` (3-4 chamfer, within
// 8% of the Euclidean distance); large where there are no seeds.
std::vector<float> distanceTo(const Mask& seeds)
{
    constexpr int kFar = 1 << 20;
    std::vector<int> d(seeds.size());
    for (size_t i = 0; i < d.size(); ++i) d[i] = seeds[i] ? 0 : kFar;
    auto relax = [&](int x, int y, int dx, int dy, int cost) {
        const int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= kSize || ny >= kSize) return;
        int& here = d[size_t(y) * kSize + x];
        here = std::min(here, d[size_t(ny) * kSize + nx] + cost);
    };
    for (int y = 0; y < kSize; ++y) {
        for (int x = 0; x < kSize; ++x) {
            relax(x, y, -1, 0, 3);
            relax(x, y, -1, -1, 4);
            relax(x, y, 0, -1, 3);
            relax(x, y, 1, -1, 4);
        }
    }
    for (int y = kSize - 1; y >= 0; --y) {
        for (int x = kSize - 1; x >= 0; --x) {
            relax(x, y, 1, 0, 3);
            relax(x, y, 1, 1, 4);
            relax(x, y, 0, 1, 3);
            relax(x, y, -1, 1, 4);
        }
    }
    std::vector<float> out(d.size());
    for (size_t i = 0; i < d.size(); ++i) out[i] = float(d[i]) / 3.0f;
    return out;
}

Mask invert(const Mask& mask)
{
    Mask out(mask.size());
    for (size_t i = 0; i < mask.size(); ++i) out[i] = !mask[i];
    return out;
}

// What the outline checks found in one picture.
struct InkReport {
    int ink = 0;             // ink pixels
    int outside = 0;         // ink farther than kOutside px outside the footprint
    int deepInside = 0;      // ink farther than kInside px inside `region` (when given)
    float covered = 0.0f;    // share of the outline with ink within kReach px
};

constexpr float kOutside = 6.0f, kInside = 6.0f, kReach = 3.0f;

InkReport inspect(const Mask& ink, const Mask& inside, const Mask* region)
{
    InkReport r;
    const std::vector<float> toFootprint = distanceTo(inside);
    const std::vector<float> toInk = distanceTo(ink);
    std::vector<float> depth;
    if (region) depth = distanceTo(invert(*region));
    const Mask edge = outline(inside);
    int edgePixels = 0, reached = 0;
    for (size_t i = 0; i < ink.size(); ++i) {
        if (edge[i]) {
            ++edgePixels;
            reached += toInk[i] <= kReach;
        }
        if (!ink[i]) continue;
        ++r.ink;
        r.outside += toFootprint[i] > kOutside;
        if (region) r.deepInside += depth[i] > kInside;
    }
    r.covered = edgePixels ? float(reached) / float(edgePixels) : 0.0f;
    return r;
}

// Of the pixels a stroke darkened on white, the share that is neither nearly white nor at the
// stroke's full darkness: the soft coverage of a texture's alpha.
float intermediateShare(const PngImage& image)
{
    int marked = 0, soft = 0;
    for (size_t i = 0; i < image.rgba.size(); i += 4) {
        const int v = image.rgba[i];
        if (v > 235) continue;
        ++marked;
        soft += v > 60;
    }
    return marked ? float(soft) / float(marked) : 0.0f;
}

} // namespace

TEST(StrokeTexture, EveryKindHasCapsAndSoftCoverage)
{
    std::vector<std::vector<uint8_t>> alphas;
    for (int kind = 0; kind < 4; ++kind) {
        SCOPED_TRACE(kind);
        PngImage texture;
        StrokeTexture::generate(StrokeTexture::Kind(kind), texture);
        ASSERT_EQ(texture.width, StrokeTexture::kWidth);
        ASSERT_EQ(texture.height, StrokeTexture::kHeight);
        std::vector<uint8_t> alpha;
        int opaque = 0, clear = 0, soft = 0;
        for (size_t i = 3; i < texture.rgba.size(); i += 4) {
            const uint8_t a = texture.rgba[i];
            alpha.push_back(a);
            opaque += a >= 200;
            clear += a <= 16;
            soft += a > 16 && a < 200;
        }
        const float n = float(alpha.size());
        EXPECT_GT(opaque / n, 0.05f);
        EXPECT_GT(clear / n, 0.05f);
        EXPECT_GT(soft / n, 0.05f) << "no intermediate alphas";
        // The caps taper: the first and last columns hold less ink than the middle one.
        auto column = [&](int x) {
            int sum = 0;
            for (int y = 0; y < texture.height; ++y) sum += alpha[size_t(y) * texture.width + x];
            return sum;
        };
        EXPECT_LT(column(0), column(texture.width / 2));
        EXPECT_LT(column(texture.width - 1), column(texture.width / 2));
        alphas.push_back(alpha);
    }
    for (size_t a = 0; a < alphas.size(); ++a)
        for (size_t b = a + 1; b < alphas.size(); ++b) EXPECT_NE(alphas[a], alphas[b]) << a << b;
}

TEST(StrokeRendering, EveryLookInksTheOutlinesOfEveryShapeAndHidesHiddenLines)
{
    StyleHarness harness(kSize, kSize);
    ASSERT_TRUE(harness.ok());
    const glm::vec4 red(0.85f, 0.35f, 0.3f, 1.0f), blue(0.35f, 0.5f, 0.85f, 1.0f);
    const glm::mat4 sphereMv = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -6)),
                                           0.4f, glm::vec3(1, 1, 0));
    const glm::mat4 torusMv = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -8)),
                                          glm::radians(35.0f), glm::vec3(1, 0.2f, 0));
    const glm::mat4 cubeMv = glm::rotate(
        glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -6)), 0.5f, glm::vec3(1, 0, 0)),
        0.6f, glm::vec3(0, 1, 0));
    const reconstruct::Batch nearSphere = sphereBatch(
        glm::translate(glm::mat4(1.0f), glm::vec3(-0.7f, 0.1f, -5.0f)), 1.0f, 40, 20, red);
    struct Shot {
        const char* name;
        std::vector<reconstruct::Batch> batches;
        // Where no ink may be deeper than kInside px: the smooth sphere's inside (no creases,
        // no inner silhouettes), the near sphere hiding part of the far one (hidden lines).
        std::vector<reconstruct::Batch> clean;
    };
    const std::vector<Shot> shots = {
        {"sphere", {sphereBatch(sphereMv, 1.5f, 48, 24, red)},
         {sphereBatch(sphereMv, 1.5f, 48, 24, red)}},
        {"torus", {torusBatch(torusMv, 2.0f, 0.7f, 48, 24)}, {}},
        {"cube", {boxBatch(cubeMv, glm::vec3(1.0f), blue)}, {}},
        {"two_spheres",
         {nearSphere, sphereBatch(glm::translate(glm::mat4(1.0f), glm::vec3(0.8f, 0.0f, -7.5f)),
                                  1.6f, 40, 20, blue, 2)},
         {nearSphere}},
    };
    // Looks after the first must each change the picture, except "query" (the same lines
    // through the other visibility test).
    const std::vector<std::pair<std::string, std::string>> looks = {
        {"default", ""},
        {"sketchy", "strokes.renderer=sketchy"},
        {"ink", "strokes.texture=ink"},
        {"brush", "strokes.texture=brush,strokes.width=5,strokes.max_length=140"},
        {"chalk", "strokes.texture=chalk,strokes.width=4"},
        {"query", "strokes.visibility=query"},
        {"light", "strokes.renderer=sketchy,strokes.width_mode=light,strokes.min_width=0.8,"
                  "strokes.max_width=4"},
        {"depth_width", "strokes.texture=ink,strokes.width_mode=depth,strokes.min_width=1,"
                        "strokes.max_width=6"},
        {"zbuffer", "strokes.renderer=sketchy,strokes.zbuffer=on,strokes.jitter_mode=normal,"
                    "strokes.jitter=1.5"},
    };
    const glm::vec4 green(0, 1, 0, 1);
    std::string error;
    for (const Shot& shot : shots) {
        SCOPED_TRACE(shot.name);
        const auto scene = harness.makeScene(shot.batches, perspective());
        PngImage toon, cover;
        ASSERT_TRUE(harness.render(scene, "toon", "", toon, error)) << error;
        ASSERT_TRUE(harness.render(scene, "toon", "", cover, error, green)) << error;
        const Mask inside = footprint(cover, glm::u8vec3(0, 255, 0));
        Mask clean;
        if (!shot.clean.empty()) {
            PngImage cleanCover;
            ASSERT_TRUE(harness.render(harness.makeScene(shot.clean, perspective()), "toon", "",
                                       cleanCover, error, green))
                << error;
            clean = footprint(cleanCover, glm::u8vec3(0, 255, 0));
        }
        PngImage white = toon;
        std::fill(white.rgba.begin(), white.rgba.end(), uint8_t(255));
        std::vector<PngImage> alone;
        for (const auto& [look, config] : looks) {
            SCOPED_TRACE(look);
            // Strokes alone on white, then over toon shading (ink = darker than toon alone).
            for (const char* chain : {"strokes", "toon+strokes"}) {
                SCOPED_TRACE(chain);
                const bool overToon = chain[0] == 't';
                PngImage image;
                ASSERT_TRUE(harness.render(scene, chain, config, image, error)) << error;
                const InkReport r = inspect(darker(image, overToon ? toon : white), inside,
                                            clean.empty() ? nullptr : &clean);
                EXPECT_EQ(r.outside, 0) << "ink far from the objects (of " << r.ink << ")";
                EXPECT_EQ(r.deepInside, 0) << "ink inside a smooth or hiding object";
                EXPECT_GE(r.covered, 0.9f) << "outline not inked";
                if (overToon) continue;
                // Textured strokes draw their texture's soft coverage; sketchy lines and
                // the ink texture are mostly solid.
                const float soft = intermediateShare(image);
                if (look == "default" || look == "brush" || look == "chalk") {
                    EXPECT_GT(soft, 0.8f) << "no soft coverage";
                }
                if (look == "sketchy" || look == "ink") {
                    EXPECT_LT(soft, 0.7f);
                }
                alone.push_back(image);
            }
        }
        // Each look changes the picture; the textured ones draw soft coverage, the sketchy
        // lines mostly full ink.
        ASSERT_EQ(alone.size(), looks.size());
        for (size_t a = 0; a < looks.size(); ++a) {
            for (size_t b = a + 1; b < looks.size(); ++b) {
                if (looks[a].first == "query" || looks[b].first == "query") continue;
                EXPECT_NE(alone[a].rgba, alone[b].rgba) << looks[a].first << " = "
                                                        << looks[b].first;
            }
        }
    }
}
