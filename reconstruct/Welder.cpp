#include "reconstruct/Welder.h"

#include <algorithm>
#include <cmath>

#include "reconstruct/ObjectMesh.h"

namespace nprgl::reconstruct {

namespace {

constexpr uint64_t kEmpty = ~uint64_t(0);
constexpr int kCellBits = 21; // three coordinates in 63 bits, so no key equals kEmpty
constexpr float kMaxCells = float(1u << 20);
constexpr float kMaxCoord = float((1u << kCellBits) - 1);

inline uint64_t cellKey(uint32_t x, uint32_t y, uint32_t z)
{
    return uint64_t(x) | (uint64_t(y) << kCellBits) | (uint64_t(z) << (2 * kCellBits));
}

inline bool isFinite(const glm::vec3& p)
{
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

} // namespace

uint32_t* Welder::findCell(uint64_t key)
{
    const size_t mask = mKeys.size() - 1;
    size_t slot = size_t((key * 0x9E3779B97F4A7C15ull) >> mShift);
    while (true) {
        if (mKeys[slot] == key) return &mHeads[slot];
        if (mKeys[slot] == kEmpty) {
            mKeys[slot] = key;
            mHeads[slot] = kNoIndex;
            return &mHeads[slot];
        }
        slot = (slot + 1) & mask;
    }
}

uint32_t Welder::weld(const Vertex* vertices, size_t count, const glm::vec3& lo,
                      const glm::vec3& hi, float tolerance, std::vector<uint32_t>& weld,
                      std::vector<uint32_t>& rep)
{
    weld.resize(count);
    rep.clear();
    mNext.clear();
    mPositions.clear();

    // Load at most 1/2; a table of the previous size is reused.
    size_t capacity = 16;
    mShift = 60;
    while (capacity < 2 * count) {
        capacity *= 2;
        --mShift;
    }
    mKeys.assign(capacity, kEmpty);
    mHeads.resize(capacity);

    // Cells much larger than the tolerance, so a position's neighbourhood usually lies in its
    // own cell (one lookup); never so small that a coordinate needs more than 20 bits.
    const float extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z, 0.0f});
    float cell = std::max(16.0f * tolerance, extent / kMaxCells);
    if (!(cell > 0.0f) || !std::isfinite(cell)) cell = 1.0f;
    const float inv = 1.0f / cell;
    const float reach = tolerance * inv;
    const float tol2 = tolerance * tolerance;

    auto coord = [](float f) { return uint32_t(std::clamp(f, 0.0f, kMaxCoord)); };
    for (size_t i = 0; i < count; ++i) {
        const glm::vec3& p = vertices[i].position;
        if (!isFinite(p)) {
            weld[i] = kNoIndex;
            continue;
        }
        const glm::vec3 f = (p - lo) * inv;
        const uint32_t cx = coord(f.x), cy = coord(f.y), cz = coord(f.z);
        uint32_t* own = findCell(cellKey(cx, cy, cz));
        uint32_t found = kNoIndex;
        for (uint32_t id = *own; id != kNoIndex; id = mNext[id]) {
            const glm::vec3 d = mPositions[id] - p;
            if (glm::dot(d, d) <= tol2) {
                found = id;
                break;
            }
        }
        if (found == kNoIndex) {
            // Near a cell border the tolerance sphere reaches into the neighbours.
            const uint32_t x0 = coord(f.x - reach), x1 = coord(f.x + reach);
            const uint32_t y0 = coord(f.y - reach), y1 = coord(f.y + reach);
            const uint32_t z0 = coord(f.z - reach), z1 = coord(f.z + reach);
            if (x0 != x1 || y0 != y1 || z0 != z1) {
                for (uint32_t z = z0; z <= z1 && found == kNoIndex; ++z) {
                    for (uint32_t y = y0; y <= y1 && found == kNoIndex; ++y) {
                        for (uint32_t x = x0; x <= x1 && found == kNoIndex; ++x) {
                            if (x == cx && y == cy && z == cz) continue;
                            // Look up without inserting: most neighbour cells are empty.
                            const uint64_t key = cellKey(x, y, z);
                            const size_t mask = mKeys.size() - 1;
                            size_t slot = size_t((key * 0x9E3779B97F4A7C15ull) >> mShift);
                            while (mKeys[slot] != kEmpty && mKeys[slot] != key)
                                slot = (slot + 1) & mask;
                            if (mKeys[slot] == kEmpty) continue;
                            for (uint32_t id = mHeads[slot]; id != kNoIndex; id = mNext[id]) {
                                const glm::vec3 d = mPositions[id] - p;
                                if (glm::dot(d, d) <= tol2) {
                                    found = id;
                                    break;
                                }
                            }
                        }
                    }
                }
            }
        }
        if (found == kNoIndex) {
            found = uint32_t(rep.size());
            rep.push_back(uint32_t(i));
            mPositions.push_back(p);
            mNext.push_back(*own);
            *own = found;
        }
        weld[i] = found;
    }
    return uint32_t(rep.size());
}

} // namespace nprgl::reconstruct
