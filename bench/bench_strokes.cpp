// Geometric strokes, CPU stages per frame: extraction (eq. 4.1) with chaining, projection,
// depth visibility (against a depth buffer rasterised on the CPU before timing), simplification
// and stroke building, and the quad generation of the renderer; on UV spheres and tori of
// 10k, 100k and 1M faces, viewed from an eye that turns around them. Prints the median CPU time
// of each stage over the frames. Then, in an OSMesa context, the two visibility methods side by
// side on the same lines of the same frames: depth (read-back + sampling) against occlusion
// queries, in wall time (the GL work runs in the driver's threads), alternating which goes
// first. Usage: bench_strokes [frames] (Release/RelWithDebInfo)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include <GL/gl.h>
#include <glm/gtc/matrix_transform.hpp>

#include "reconstruct/Reconstructor.h"
#include "reconstruct/Silhouette.h"
#include "styles/strokes/ChainExtractor.h"
#include "styles/strokes/ChainProjector.h"
#include "styles/strokes/DepthVisibility.h"
#include "styles/strokes/JitterTable.h"
#include "styles/strokes/StrokeBuilder.h"
#include "styles/strokes/StrokePainter.h"
#include "styles/strokes/StrokeSimplifier.h"
#if NPRGL_BENCH_GL
#include "styles/MeshBuffers.h"
#include "styles/ShaderProgram.h"
#include "styles/strokes/QueryVisibility.h"
#include "tests/support/StyleHarness.h"

#include <glm/gtc/type_ptr.hpp>
#endif

using namespace nprgl;
using namespace nprgl::reconstruct;
using namespace nprgl::styles::strokes;

namespace {

constexpr int kWidth = 1024, kHeight = 768;
constexpr float kPi = 3.14159265f;

double cpuMs()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

Vertex vertex(glm::vec3 p, glm::vec3 n)
{
    Vertex v{};
    v.position = p;
    v.normal = n;
    v.color = glm::vec4(0.8f, 0.6f, 0.2f, 1.0f);
    v.hasNormal = true;
    return v;
}

// A UV sphere (2 * slices * (stacks - 1) faces) or a torus (2 * rings * sides) as triangles.
Batch sphere(int slices, int stacks)
{
    Batch b;
    b.mode = GL_TRIANGLES;
    auto point = [&](int i, int j) {
        const float theta = kPi * float(j) / float(stacks);
        const float phi = 2.0f * kPi * float(i % slices) / float(slices);
        const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta),
                          std::sin(theta) * std::sin(phi));
        return vertex(1.5f * n, n);
    };
    for (int j = 0; j < stacks; ++j) {
        for (int i = 0; i < slices; ++i) {
            const Vertex a = point(i, j), c = point(i + 1, j), d = point(i + 1, j + 1),
                         e = point(i, j + 1);
            if (j > 0) b.vertices.insert(b.vertices.end(), {a, c, e});
            if (j < stacks - 1) b.vertices.insert(b.vertices.end(), {c, d, e});
        }
    }
    b.contentHash = hashBatch(b);
    return b;
}

Batch torus(int rings, int sides)
{
    Batch b;
    b.mode = GL_TRIANGLES;
    auto point = [&](int i, int j) {
        const float theta = 2.0f * kPi * float(i % rings) / float(rings);
        const float phi = 2.0f * kPi * float(j % sides) / float(sides);
        const glm::vec3 n(std::cos(phi) * std::cos(theta), std::sin(phi),
                          std::cos(phi) * std::sin(theta));
        return vertex(glm::vec3(1.6f * std::cos(theta), 0.0f, 1.6f * std::sin(theta)) + 0.55f * n,
                      n);
    };
    for (int i = 0; i < rings; ++i) {
        for (int j = 0; j < sides; ++j) {
            const Vertex a = point(i, j), c = point(i + 1, j), d = point(i + 1, j + 1),
                         e = point(i, j + 1);
            b.vertices.insert(b.vertices.end(), {a, e, d, a, d, c});
        }
    }
    b.contentHash = hashBatch(b);
    return b;
}

// The scene's depth buffer, as the compositor's pre-pass leaves it: a plain z-buffer
// rasteriser over the mesh (window depth is linear on screen). Not timed.
void rasterise(const ObjectMesh& mesh, const glm::mat4& mvp, std::vector<float>& depth)
{
    depth.assign(size_t(kWidth) * kHeight, 1.0f);
    const Mesh::Point* points = mesh.mesh.points();
    std::vector<glm::vec3> window(mesh.vertexCount());
    for (uint32_t v = 0; v < mesh.vertexCount(); ++v) {
        const glm::vec4 c = mvp * glm::vec4(points[v][0], points[v][1], points[v][2], 1.0f);
        const glm::vec3 n = glm::vec3(c) / c.w;
        window[v] = glm::vec3((n.x + 1.0f) * 0.5f * kWidth, (n.y + 1.0f) * 0.5f * kHeight,
                              0.5f * n.z + 0.5f);
    }
    for (uint32_t f = 0; f < mesh.faceCount(); ++f) {
        const glm::vec3 a = window[mesh.faceVertices[3 * f]];
        const glm::vec3 b = window[mesh.faceVertices[3 * f + 1]];
        const glm::vec3 c = window[mesh.faceVertices[3 * f + 2]];
        const float area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (area == 0.0f) continue;
        const int x0 = std::max(0, int(std::floor(std::min({a.x, b.x, c.x}))));
        const int x1 = std::min(kWidth - 1, int(std::ceil(std::max({a.x, b.x, c.x}))));
        const int y0 = std::max(0, int(std::floor(std::min({a.y, b.y, c.y}))));
        const int y1 = std::min(kHeight - 1, int(std::ceil(std::max({a.y, b.y, c.y}))));
        for (int y = y0; y <= y1; ++y) {
            for (int x = x0; x <= x1; ++x) {
                const float px = float(x) + 0.5f, py = float(y) + 0.5f;
                const float w0 = ((b.x - px) * (c.y - py) - (b.y - py) * (c.x - px)) / area;
                const float w1 = ((c.x - px) * (a.y - py) - (c.y - py) * (a.x - px)) / area;
                const float w2 = 1.0f - w0 - w1;
                if (w0 < 0 || w1 < 0 || w2 < 0) continue;
                const float z = w0 * a.z + w1 * b.z + w2 * c.z;
                float& d = depth[size_t(y) * kWidth + x];
                d = std::min(d, z);
            }
        }
    }
}

struct Stage {
    const char* name;
    std::vector<double> ms;
};

#if NPRGL_BENCH_GL

double wallMs()
{
    using namespace std::chrono;
    return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

Batch placed(Batch b, const glm::mat4& modelview)
{
    b.modelview = modelview;
    b.contentHash = hashBatch(b);
    return b;
}

// Depth read-back + DepthVisibility against QueryVisibility on the silhouettes of every object,
// per frame: the depth pre-pass is drawn and finished first (both methods need it), and the
// lines are extracted and projected (untimed); then the two methods classify copies of the
// same lines, alternating which runs first. Prints the median wall ms of each and the ratio.
void visibilitySideBySide(int frames)
{
    constexpr int kSize = 512;
    test::StyleHarness harness(kSize, kSize);
    if (!harness.ok()) {
        std::printf("visibility: no OSMesa context, skipped\n");
        return;
    }
    const styles::GlFunctions& gl = harness.gl();
    std::string error;
    styles::ShaderProgram depthProgram;
    QueryVisibility queries;
    if (!depthProgram.build(gl, test::StyleHarness::depthVertexShader(),
                            test::StyleHarness::depthFragmentShader(), error) ||
        !queries.init(gl, error)) {
        std::printf("visibility: %s\n", error.c_str());
        return;
    }
    GLuint vao = 0;
    gl.GenVertexArrays(1, &vao);
    styles::MeshBuffers buffers;
    const glm::mat4 projection = glm::perspective(glm::radians(40.0f), 1.0f, 1.0f, 20.0f);
    struct Case {
        const char* name;
        std::vector<Batch> batches; // modelviews relative to the turning eye
    };
    const Case cases[] = {
        {"half-hidden spheres 4.6k",
         {placed(sphere(48, 25), glm::scale(glm::translate(glm::mat4(1.0f),
                                                           glm::vec3(-0.7f, 0.1f, 1.25f)),
                                            glm::vec3(1.0f / 1.5f))),
          placed(sphere(48, 25), glm::scale(glm::translate(glm::mat4(1.0f),
                                                           glm::vec3(0.8f, 0.0f, -1.25f)),
                                            glm::vec3(1.6f / 1.5f)))}},
        {"torus 100k", {placed(torus(316, 158), glm::mat4(1.0f))}},
    };
    std::printf("\nvisibility side by side, %dx%d OSMesa, wall ms per frame (median of %d "
                "frames, eye turning)\n",
                kSize, kSize, frames);
    std::printf("%-26s %9s %8s | %9s %9s | %7s\n", "scene", "sil.edges", "queries", "depth",
                "query", "q/d");
    std::vector<float> depth(size_t(kSize) * kSize);
    for (const Case& c : cases) {
        std::vector<double> depthMs, queryMs;
        size_t edges = 0;
        uint32_t queryCount = 0;
        for (int frame = 0; frame < frames; ++frame) {
            const glm::mat4 eye =
                glm::rotate(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -7.5f)),
                                        0.5f + 0.1f * float(frame), glm::vec3(1, 0, 0)),
                            0.37f * float(frame), glm::vec3(0, 1, 0));
            std::vector<Batch> batches;
            for (const Batch& b : c.batches) batches.push_back(placed(b, eye * b.modelview));
            const styles::Scene scene = harness.makeScene(batches, projection);

            gl.BindVertexArray(vao);
            gl.Viewport(0, 0, kSize, kSize);
            gl.ClearDepth(1.0);
            gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            gl.Enable(GL_DEPTH_TEST);
            gl.DepthFunc(GL_LESS);
            gl.UseProgram(depthProgram.id());
            for (const auto& o : scene.objects) {
                const glm::mat4 mvp = o.projection * o.modelview;
                gl.UniformMatrix4fv(depthProgram.uniform(gl, "mvp"), 1, GL_FALSE,
                                    glm::value_ptr(mvp));
                buffers.draw(gl, *o.mesh);
            }
            gl.Finish();

            std::vector<Polylines> lines(scene.objects.size());
            ChainExtractor extractor;
            ChainProjector projector;
            EdgeChains chains;
            edges = 0;
            for (size_t k = 0; k < scene.objects.size(); ++k) {
                const auto& o = scene.objects[k];
                extractor.extract(*o.mesh, eyeInObjectSpace(o.modelview), {}, chains);
                projector.project(*o.mesh, chains, o.modelview, o.projection, scene.viewport,
                                  0.01f, lines[k]);
                edges += chains.edges.size();
            }
            DepthVisibility depthVisibility;
            auto runDepth = [&] {
                std::vector<Polylines> work = lines;
                const double start = wallMs();
                gl.ReadPixels(0, 0, kSize, kSize, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
                const DepthImage image{depth.data(), 0, 0, kSize, kSize};
                for (size_t k = 0; k < work.size(); ++k)
                    depthVisibility.classify(*scene.objects[k].mesh, image, {}, work[k]);
                depthMs.push_back(wallMs() - start);
            };
            auto runQueries = [&] {
                std::vector<Polylines> work = lines;
                gl.BindVertexArray(vao);
                queryCount = 0;
                const double start = wallMs();
                for (size_t k = 0; k < work.size(); ++k) {
                    queries.classify(gl, *scene.objects[k].mesh, scene.viewport, {}, work[k]);
                    queryCount += queries.queryCount();
                }
                queryMs.push_back(wallMs() - start);
            };
            if (frame % 2) {
                runQueries();
                runDepth();
            } else {
                runDepth();
                runQueries();
            }
        }
        const double d = median(depthMs), q = median(queryMs);
        std::printf("%-26s %9zu %8u | %9.3f %9.3f | %7.1f\n", c.name, edges, queryCount, d, q,
                    d > 0 ? q / d : 0.0);
    }
    std::printf("depth: glReadPixels of the depth buffer + sampling; query: two occlusion "
                "queries per segment, refined, each result waited on; q/d: query / depth\n");
    queries.destroy(gl);
    buffers.destroy(gl);
    depthProgram.destroy(gl);
    gl.DeleteVertexArrays(1, &vao);
}

#endif

} // namespace

int main(int argc, char** argv)
{
    const int frames = argc > 1 ? std::max(1, std::atoi(argv[1])) : 9;
    struct Model {
        const char* name;
        Batch batch;
    };
    const Model models[] = {
        {"sphere 10k", sphere(100, 51)},  {"torus 10k", torus(100, 50)},
        {"sphere 100k", sphere(316, 159)}, {"torus 100k", torus(316, 158)},
        {"sphere 1M", sphere(1000, 501)},  {"torus 1M", torus(1000, 500)},
    };
    const glm::mat4 projection =
        glm::perspective(glm::radians(40.0f), float(kWidth) / kHeight, 1.0f, 30.0f);
    const glm::ivec4 viewport(0, 0, kWidth, kHeight);
    std::printf("CPU ms per frame (median of %d frames, eye turning), %dx%d viewport\n", frames,
                kWidth, kHeight);
    std::printf("%-12s %8s %7s %7s | %7s %7s %7s %7s %7s %7s | %8s %7s\n", "model", "faces",
                "sil.edges", "strokes", "test", "extract", "project", "depthvis", "simplify",
                "build", "total", "paint");
    for (const Model& model : models) {
        Reconstructor reconstructor;
        std::vector<FrameObject> objects;
        std::vector<Batch> batches{model.batch};
        reconstructor.build(batches, objects);
        const ObjectMesh& mesh = *objects[0].mesh;
        ChainExtractor extractor;
        ChainProjector projector;
        DepthVisibility visibility;
        StrokeSimplifier simplifier;
        StrokeBuilder builder;
        StrokePainter painter;
        JitterTable jitter;
        EdgeChains chains;
        Polylines lines, strokes;
        std::vector<EdgeIndex> silhouettes;
        std::vector<StrokeVertex> vertices;
        std::vector<float> depth;
        Stage test{"test", {}}, extract{"extract", {}}, project{"project", {}},
            vis{"depthvis", {}}, simplify{"simplify", {}}, build{"build", {}}, paint{"paint", {}};
        std::vector<double> total;
        size_t silhouetteCount = 0, strokeCount = 0;
        StrokeBuilder::Options buildOptions;
        StrokePainter::Options paintOptions;
        for (int frame = 0; frame < frames; ++frame) {
            const float angle = 0.37f * float(frame);
            const glm::mat4 modelview =
                glm::rotate(glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, -6.5f)),
                                        0.5f + 0.1f * float(frame), glm::vec3(1, 0, 0)),
                            angle, glm::vec3(0, 1, 0));
            rasterise(mesh, projection * modelview, depth);
            const DepthImage image{depth.data(), 0, 0, kWidth, kHeight};
            const glm::vec3 eye = eyeInObjectSpace(modelview);
            double t = cpuMs(), start = t;
            auto lap = [&](Stage& s) {
                const double now = cpuMs();
                s.ms.push_back(now - t);
                t = now;
            };
            silhouetteEdges(mesh, eye, silhouettes); // eq. 4.1 alone, for reference
            lap(test);
            start = t;
            extractor.extract(mesh, eye, {}, chains);
            lap(extract);
            projector.project(mesh, chains, modelview, projection, viewport, 0.01f, lines);
            lap(project);
            visibility.classify(mesh, image, {}, lines);
            lap(vis);
            simplifier.simplify(lines);
            simplifier.removeFolds(lines, 3.0f);
            lap(simplify);
            builder.build(lines, buildOptions, strokes);
            lap(build);
            total.push_back(t - start);
            StrokePainter::View view;
            view.modelview = modelview;
            view.projection = projection;
            view.viewport = viewport;
            vertices.clear();
            painter.paint(mesh, strokes, view, paintOptions, jitter, vertices);
            lap(paint);
            silhouetteCount = chains.edges.size();
            strokeCount = strokes.count();
        }
        std::printf("%-12s %8u %9zu %7zu | %7.3f %7.3f %7.3f %8.3f %8.3f %7.3f | %8.3f %7.3f\n",
                    model.name, mesh.faceCount(), silhouetteCount, strokeCount,
                    median(test.ms), median(extract.ms), median(project.ms), median(vis.ms),
                    median(simplify.ms), median(build.ms), median(total), median(paint.ms));
    }
    std::printf("test: eq. 4.1 over all edges alone (reference); extract: test + chaining; "
                "total: extract .. build (targets: 10k <= 2 ms, 100k <= 20 ms)\n");
#if NPRGL_BENCH_GL
    visibilitySideBySide(frames);
#endif
    return 0;
}
