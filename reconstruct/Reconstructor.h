#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "reconstruct/Batch.h"
#include "reconstruct/MeshBuilder.h"
#include "reconstruct/MeshCache.h"
#include "reconstruct/ObjectMesh.h"
#include "reconstruct/ReconstructParams.h"

namespace nprgl::reconstruct {

// One object of a frame: the mesh and where the program drew it.
struct FrameObject {
    std::shared_ptr<const ObjectMesh> mesh;
    glm::mat4 modelview{1.0f};
    uint32_t firstBatch = 0; // index into the frame's batches
    uint32_t batchCount = 0;
};

// Turns a frame's stylised batches into welded meshes, one per object, and caches them:
// - consecutive batches of one pass whose modelviews are bitwise equal (all 16 floats) form
//   one object
//   and are welded together (a glxgears gear is several glBegin batches);
// - an object whose batches are unchanged (content hashes, modes, materials) costs a hash
//   lookup; one whose modes and vertex counts are unchanged and whose vertices only moved
//   keeps its connectivity and recomputes positions, normals and edge classes; anything else
//   is rebuilt;
// - the cache is bounded by bytes, least recently used first out.
// Not thread-safe: one Reconstructor per thread (or per GL context). Never throws, never
// writes to stdout or stderr.
class Reconstructor {
public:
    explicit Reconstructor(const ReconstructParams& params = {},
                           size_t cacheBytes = size_t(256) << 20);

    // The frame's objects in drawing order. Passing last frame's vector back in releases the
    // meshes it holds first, so they can be updated in place instead of copied. If memory
    // runs out, `out` ends early and cacheStats().failures counts it.
    void build(const std::vector<Batch>& frameBatches, std::vector<FrameObject>& out) noexcept;
    std::vector<FrameObject> build(const std::vector<Batch>& frameBatches) noexcept;

    CacheStats cacheStats() const;
    void clearCache() noexcept;
    void setCacheBudget(size_t bytes) noexcept;
    const ReconstructParams& params() const { return mParams; }
    // Other parameters make other meshes: clears the cache.
    void setParams(const ReconstructParams& params) noexcept;

private:
    struct Group {
        uint32_t first;
        uint32_t count;
        uint64_t contentKey;
        uint64_t structureKey;
    };
    struct KeyItem { // hashed per batch; explicit fields, no padding
        uint64_t contentHash;
        uint32_t materialId;
        uint32_t mode;
        uint32_t vertexCount;
        uint32_t zero;
    };

    void groupBatches(const std::vector<Batch>& batches);
    std::shared_ptr<const ObjectMesh> obtain(const Batch* batches, const Group& group);

    ReconstructParams mParams;
    MeshCache mCache;
    MeshBuilder mBuilder;
    CacheStats mCounters;
    uint64_t mFrame = 0;
    std::vector<Group> mGroups;
    std::vector<uint64_t> mFrameKeys; // sorted content keys of this frame's objects
    std::vector<KeyItem> mKeyItems;
    std::vector<MeshCache::Entry*> mCandidates;
};

} // namespace nprgl::reconstruct
