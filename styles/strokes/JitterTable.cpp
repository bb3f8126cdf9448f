#include "styles/strokes/JitterTable.h"

namespace nprgl::styles::strokes {

namespace {

constexpr uint64_t kForgetAfter = 16; // frames

uint64_t mix(uint64_t x)
{
    // splitmix64 finaliser: cheap and well spread.
    x += 0x9e3779b97f4a7c15ull;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
}

float unit(uint64_t bits) { return float(bits >> 40) * (2.0f / float(1u << 24)) - 1.0f; }

} // namespace

glm::vec3 JitterTable::offset(uint32_t seed, uint32_t pass, uint32_t vertex)
{
    const uint64_t h = mix((uint64_t(seed) << 40) ^ (uint64_t(pass) << 32) ^ vertex);
    return {unit(mix(h ^ 1)), unit(mix(h ^ 2)), unit(mix(h ^ 3))};
}

const glm::vec3* JitterTable::offsets(const reconstruct::ObjectMesh& mesh, uint32_t passes,
                                      uint32_t seed)
{
    Entry& entry = mEntries[&mesh];
    entry.lastUsed = mFrame;
    const uint32_t vertices = mesh.vertexCount();
    if (entry.contentKey != mesh.contentKey || entry.vertices != vertices ||
        entry.passes != passes || entry.seed != seed || entry.values.empty()) {
        entry.contentKey = mesh.contentKey;
        entry.vertices = vertices;
        entry.passes = passes;
        entry.seed = seed;
        entry.values.resize(size_t(passes) * vertices + 1);
        for (uint32_t p = 0; p < passes; ++p) {
            for (uint32_t v = 0; v < vertices; ++v)
                entry.values[size_t(p) * vertices + v] = offset(seed, p, v);
        }
    }
    return entry.values.data();
}

void JitterTable::endFrame()
{
    ++mFrame;
    for (auto it = mEntries.begin(); it != mEntries.end();) {
        if (mFrame - it->second.lastUsed > kForgetAfter) it = mEntries.erase(it);
        else ++it;
    }
}

} // namespace nprgl::styles::strokes
