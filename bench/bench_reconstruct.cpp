// Reconstruction timings against the targets of the issue: cold build of 10k / 100k / 1M
// triangles (a torus sent as one GL_QUAD_STRIP per ring, with normals), the per-frame cost of
// a cached object, and the per-frame update of an animated mesh with fixed topology.
// Prints medians. Usage: bench_reconstruct [repetitions]   (build it Release/RelWithDebInfo)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include <GL/gl.h>

#include "reconstruct/Reconstructor.h"

using namespace nprgl::reconstruct;

namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start)
{
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

double median(std::vector<double> v)
{
    std::sort(v.begin(), v.end());
    const size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// rings * sides quads = 2 * rings * sides triangles; the wave moves vertices along their
// normals (an animated mesh with fixed topology).
std::vector<Batch> torus(int rings, int sides, float wave)
{
    const float pi = 3.14159265f, R = 2.0f, r = 0.5f;
    std::vector<Batch> batches(rings);
    for (int i = 0; i < rings; ++i) {
        Batch& b = batches[i];
        b.mode = GL_QUAD_STRIP;
        b.vertices.reserve(2 * (sides + 1));
        for (int j = 0; j <= sides; ++j) {
            for (int ring : {i, i + 1}) {
                const float theta = 2.0f * pi * float(ring) / float(rings);
                const float phi = 2.0f * pi * float(j) / float(sides);
                const glm::vec3 n(std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta),
                                  std::sin(phi));
                const float rr = r * (1.0f + wave * std::sin(5.0f * theta + 3.0f * phi));
                Vertex v{};
                v.position = glm::vec3(R * std::cos(theta), R * std::sin(theta), 0.0f) + rr * n;
                v.normal = n;
                v.color = glm::vec4(0.8f, 0.6f, 0.2f, 1.0f);
                v.texcoord = glm::vec2(float(ring) / float(rings), float(j) / float(sides));
                v.hasNormal = true;
                b.vertices.push_back(v);
            }
        }
        b.contentHash = hashBatch(b);
    }
    return batches;
}

struct Size {
    int rings, sides;
    int triangles() const { return 2 * rings * sides; }
};

void row(const char* what, int triangles, double ms, double perTarget, double target,
         const char* unit)
{
    std::printf("%-34s %8d %10.3f ms   %8.3f %-13s (target %.3f)  %s\n", what, triangles, ms,
                perTarget, unit, target, perTarget <= target ? "ok" : "MISSED");
}

} // namespace

int main(int argc, char** argv)
{
    const int reps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
    const Size sizes[] = {{100, 50}, {500, 100}, {1000, 500}};
    std::printf("%-34s %8s %13s   %s\n", "measurement", "tris", "median", "normalised");

    for (const Size& size : sizes) {
        const int tris = size.triangles();
        const std::vector<Batch> frame = torus(size.rings, size.sides, 0.0f);
        Reconstructor reconstructor;
        std::vector<FrameObject> out;

        // Cold: nothing cached (scratch buffers warm, as for a new object in a running app).
        std::vector<double> cold;
        for (int i = 0; i < reps; ++i) {
            out.clear();
            reconstructor.clearCache();
            const auto start = Clock::now();
            reconstructor.build(frame, out);
            cold.push_back(msSince(start));
        }
        if (out.size() != 1 || out[0].mesh->faceCount() != uint32_t(tris)) {
            std::fprintf(stderr, "unexpected mesh: %u faces\n",
                         out.empty() ? 0u : out[0].mesh->faceCount());
            return 1;
        }
        const double coldMs = median(cold);
        row("cold build", tris, coldMs, coldMs * 100000.0 / tris, 50.0, "ms/100k tris");

        // Cached: the same batches again.
        std::vector<double> cached;
        const int cachedLoops = 200;
        for (int i = 0; i < reps; ++i) {
            const auto start = Clock::now();
            for (int k = 0; k < cachedLoops; ++k) reconstructor.build(frame, out);
            cached.push_back(msSince(start) / cachedLoops);
        }
        const double cachedMs = median(cached);
        row("cached frame (1 object)", tris, cachedMs, cachedMs, 0.05, "ms/object");

        // Animated: every frame moves every vertex, the topology stays. The producer hashes
        // the batches (timed separately: it is the interpreter's cost, not ours).
        const int frames = std::max(reps, 5);
        std::vector<std::vector<Batch>> animation;
        for (int f = 0; f < frames; ++f)
            animation.push_back(torus(size.rings, size.sides, 0.05f * float(f + 1)));
        std::vector<double> update, hashing;
        const CacheStats before = reconstructor.cacheStats();
        for (int f = 0; f < frames; ++f) {
            std::vector<Batch>& batches = animation[f];
            auto start = Clock::now();
            for (Batch& b : batches) b.contentHash = hashBatch(b);
            hashing.push_back(msSince(start));
            start = Clock::now();
            reconstructor.build(batches, out);
            update.push_back(msSince(start));
        }
        const CacheStats after = reconstructor.cacheStats();
        if (after.updates - before.updates != uint64_t(frames) ||
            after.rebuilds != before.rebuilds) {
            std::fprintf(stderr, "animated frames were not updates (%llu updates, %llu rebuilds)\n",
                         (unsigned long long)(after.updates - before.updates),
                         (unsigned long long)(after.rebuilds - before.rebuilds));
            return 1;
        }
        const double updateMs = median(update);
        row("animated update", tris, updateMs, updateMs * 100000.0 / tris, 2.0, "ms/100k tris");
        const double hashMs = median(hashing);
        std::printf("%-34s %8d %10.3f ms   (producer side, not part of the targets)\n",
                    "  hashing the batches", tris, hashMs);
    }

    // Many small objects: the per-object cost of a cached frame.
    {
        const int objects = 200;
        std::vector<Batch> frame;
        for (int o = 0; o < objects; ++o) {
            std::vector<Batch> t = torus(8, 6, 0.01f * float(o));
            for (Batch& b : t) {
                b.modelview[3] = glm::vec4(float(o), 0.0f, 0.0f, 1.0f);
                frame.push_back(b);
            }
        }
        Reconstructor reconstructor;
        std::vector<FrameObject> out;
        reconstructor.build(frame, out);
        std::vector<double> cached;
        for (int i = 0; i < reps; ++i) {
            const auto start = Clock::now();
            for (int k = 0; k < 20; ++k) reconstructor.build(frame, out);
            cached.push_back(msSince(start) / 20.0);
        }
        const double ms = median(cached);
        row("cached frame (200 objects)", 96 * objects, ms, ms / objects, 0.05, "ms/object");
    }
    return 0;
}
