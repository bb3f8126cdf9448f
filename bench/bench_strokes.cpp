// Geometric strokes, CPU stages per frame: extraction (eq. 4.1) with chaining, projection,
// depth visibility (against a depth buffer rasterised on the CPU before timing), simplification
// and stroke building, and the quad generation of the renderer; on UV spheres and tori of
// 10k, 100k and 1M faces, viewed from an eye that turns around them. Prints the median CPU time
// of each stage over the frames. Usage: bench_strokes [frames] (Release/RelWithDebInfo)
#include <algorithm>
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
    return 0;
}
