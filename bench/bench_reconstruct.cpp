// Reconstruction timings against the targets of the issue: cold build of 10k / 100k / 1M
// triangles (a torus sent as one GL_QUAD_STRIP per ring, with normals), the per-frame cost of
// a cached object, and the per-frame update of an animated mesh with fixed topology.
// Prints medians of wall-clock time, and of the thread's CPU time, which other processes on a
// shared machine disturb less. Usage: bench_reconstruct [repetitions] (Release/RelWithDebInfo)
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <vector>

#include <GL/gl.h>

#include "reconstruct/Reconstructor.h"

using namespace nprgl::reconstruct;

namespace {

using Clock = std::chrono::steady_clock;

double cpuMs()
{
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}

// Wall-clock and CPU milliseconds of one measurement.
struct Timer {
    Clock::time_point wall = Clock::now();
    double cpu = cpuMs();
};

struct Samples {
    std::vector<double> wall, cpu;
    void add(const Timer& t, double divisor = 1.0)
    {
        wall.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t.wall).count() /
                       divisor);
        cpu.push_back((cpuMs() - t.cpu) / divisor);
    }
};

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

// `scale` turns a time into the target's unit (per 100k triangles, per object).
void row(const char* what, int triangles, const Samples& s, double scale, double target,
         const char* unit)
{
    const double wall = median(s.wall) * scale, cpu = median(s.cpu) * scale;
    std::printf("%-28s %8d %10.3f ms %10.4f %10.4f %-13s %7.3f  %s\n", what, triangles,
                median(s.wall), wall, cpu, unit, target, wall <= target ? "ok" : "MISSED");
}

} // namespace

int main(int argc, char** argv)
{
    const int reps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
    const Size sizes[] = {{100, 50}, {500, 100}, {1000, 500}};
    std::printf("%-28s %8s %13s %10s %10s %-13s %7s\n", "measurement", "tris", "wall median",
                "wall", "cpu", "(normalised)", "target");

    for (const Size& size : sizes) {
        const int tris = size.triangles();
        const std::vector<Batch> frame = torus(size.rings, size.sides, 0.0f);
        Reconstructor reconstructor;
        std::vector<FrameObject> out;

        // Cold: nothing cached (scratch buffers warm, as for a new object in a running app).
        Samples cold;
        for (int i = 0; i < reps; ++i) {
            out.clear();
            reconstructor.clearCache();
            const Timer t;
            reconstructor.build(frame, out);
            cold.add(t);
        }
        if (out.size() != 1 || out[0].mesh->faceCount() != uint32_t(tris)) {
            std::fprintf(stderr, "unexpected mesh: %u faces\n",
                         out.empty() ? 0u : out[0].mesh->faceCount());
            return 1;
        }
        row("cold build", tris, cold, 100000.0 / tris, 50.0, "ms/100k tris");

        // Cached: the same batches again.
        Samples cached;
        const int cachedLoops = 200;
        for (int i = 0; i < reps; ++i) {
            const Timer t;
            for (int k = 0; k < cachedLoops; ++k) reconstructor.build(frame, out);
            cached.add(t, cachedLoops);
        }
        row("cached frame (1 object)", tris, cached, 1.0, 0.05, "ms/object");

        // Animated: every frame moves every vertex, the topology stays. The producer hashes
        // the batches (timed separately: it is the interpreter's cost, not ours).
        const int frames = std::max(reps, 5);
        std::vector<std::vector<Batch>> animation;
        for (int f = 0; f < frames; ++f)
            animation.push_back(torus(size.rings, size.sides, 0.05f * float(f + 1)));
        Samples update;
        std::vector<double> hashing;
        const CacheStats before = reconstructor.cacheStats();
        for (int f = 0; f < frames; ++f) {
            std::vector<Batch>& batches = animation[f];
            auto start = Clock::now();
            for (Batch& b : batches) b.contentHash = hashBatch(b);
            hashing.push_back(msSince(start));
            const Timer t;
            reconstructor.build(batches, out);
            update.add(t);
        }
        const CacheStats after = reconstructor.cacheStats();
        if (after.updates - before.updates != uint64_t(frames) ||
            after.rebuilds != before.rebuilds) {
            std::fprintf(stderr, "animated frames were not updates (%llu updates, %llu rebuilds)\n",
                         (unsigned long long)(after.updates - before.updates),
                         (unsigned long long)(after.rebuilds - before.rebuilds));
            return 1;
        }
        row("animated update", tris, update, 100000.0 / tris, 2.0, "ms/100k tris");
        std::printf("%-28s %8d %10.3f ms   (producer side, not in the targets)\n",
                    "  hashing the batches", tris, median(hashing));
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
        Samples cached;
        for (int i = 0; i < reps; ++i) {
            const Timer t;
            for (int k = 0; k < 20; ++k) reconstructor.build(frame, out);
            cached.add(t, 20.0);
        }
        row("cached frame (200 objects)", 96 * objects, cached, 1.0 / objects, 0.05,
            "ms/object");
    }
    return 0;
}
