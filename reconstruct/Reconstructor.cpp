#include "reconstruct/Reconstructor.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include <xxhash.h>

namespace nprgl::reconstruct {

namespace {

// Updating means validating every vertex; after this many refusals a rebuild is cheaper.
constexpr int kUpdateAttempts = 2;

ReconstructParams sanitized(ReconstructParams params)
{
    const ReconstructParams defaults;
    if (!(params.weldTolerance >= 0.0f) || !std::isfinite(params.weldTolerance))
        params.weldTolerance = defaults.weldTolerance;
    if (!(params.updateTolerance >= 0.0f) || !std::isfinite(params.updateTolerance))
        params.updateTolerance = defaults.updateTolerance;
    if (std::isnan(params.creaseCosine)) params.creaseCosine = defaults.creaseCosine;
    return params;
}

} // namespace

Reconstructor::Reconstructor(const ReconstructParams& params, size_t cacheBytes)
    : mParams(sanitized(params)), mCache(cacheBytes)
{
}

std::vector<FrameObject> Reconstructor::build(const std::vector<Batch>& frameBatches) noexcept
{
    std::vector<FrameObject> out;
    build(frameBatches, out);
    return out;
}

void Reconstructor::groupBatches(const std::vector<Batch>& batches)
{
    mGroups.clear();
    mFrameKeys.clear();
    const uint32_t n = uint32_t(batches.size());
    for (uint32_t first = 0; first < n;) {
        uint32_t end = first + 1;
        while (end < n && batches[end].pass == batches[first].pass &&
               std::memcmp(&batches[end].modelview, &batches[first].modelview,
                           sizeof(glm::mat4)) == 0)
            ++end;
        mKeyItems.clear();
        for (uint32_t b = first; b < end; ++b) {
            const Batch& batch = batches[b];
            KeyItem item{};
            item.contentHash = batch.contentHash != 0 ? batch.contentHash : hashBatch(batch);
            item.materialId = batch.materialId;
            item.mode = assemblyMode(batch);
            item.vertexCount = uint32_t(batch.vertices.size());
            mKeyItems.push_back(item);
        }
        Group group;
        group.first = first;
        group.count = end - first;
        group.contentKey = XXH3_64bits(mKeyItems.data(), mKeyItems.size() * sizeof(KeyItem));
        // The topology's key: modes and counts only.
        for (KeyItem& item : mKeyItems) item.contentHash = item.materialId = 0;
        group.structureKey =
            XXH3_64bits_withSeed(mKeyItems.data(), mKeyItems.size() * sizeof(KeyItem), 1);
        mGroups.push_back(group);
        mFrameKeys.push_back(group.contentKey);
        first = end;
    }
    std::sort(mFrameKeys.begin(), mFrameKeys.end());
}

std::shared_ptr<const ObjectMesh> Reconstructor::obtain(const Batch* batches,
                                                        const Group& group)
{
    if (MeshCache::Entry* entry = mCache.find(group.contentKey)) {
        if (entry->structureKey == group.structureKey) {
            entry->lastFrame = mFrame;
            ++mCounters.hits;
            return entry->mesh;
        }
        mCache.erase(entry); // a 64-bit key collision: make room for the real content
    }

    // An entry of the same structure that no object of this frame still shows: an animated
    // mesh's previous frame.
    mCache.findStructure(group.structureKey, mCandidates);
    int attempts = 0;
    for (MeshCache::Entry* entry : mCandidates) {
        if (entry->lastFrame == mFrame) continue;
        if (std::binary_search(mFrameKeys.begin(), mFrameKeys.end(), entry->contentKey))
            continue;
        if (attempts++ == kUpdateAttempts) break;
        if (!mBuilder.prepareUpdate(*entry->mesh, batches, group.count)) continue;
        try {
            // Someone still holds the old mesh: update a copy, theirs stays as it was.
            if (entry->mesh.use_count() > 1)
                entry->mesh = std::make_shared<ObjectMesh>(*entry->mesh);
            mBuilder.applyUpdate(*entry->mesh, batches, group.count, mParams);
            entry->mesh->contentKey = group.contentKey;
            entry->lastFrame = mFrame;
            mCache.rekey(entry, group.contentKey);
        } catch (...) {
            // Out of memory half-way: the entry may not match its key any more.
            mCache.erase(entry);
            throw;
        }
        ++mCounters.updates;
        std::shared_ptr<const ObjectMesh> mesh = entry->mesh;
        mCounters.evictions += mCache.trim();
        return mesh;
    }

    std::shared_ptr<ObjectMesh> mesh = mBuilder.build(batches, group.count, mParams);
    mesh->contentKey = group.contentKey;
    ++mCounters.rebuilds;
    MeshCache::Entry* entry = mCache.insert(group.contentKey, group.structureKey, mesh);
    entry->lastFrame = mFrame;
    mCounters.evictions += mCache.trim();
    return mesh;
}

void Reconstructor::build(const std::vector<Batch>& frameBatches,
                          std::vector<FrameObject>& out) noexcept
{
    out.clear();
    try {
        ++mFrame;
        groupBatches(frameBatches);
        out.reserve(mGroups.size());
        for (const Group& group : mGroups) {
            FrameObject object;
            object.mesh = obtain(&frameBatches[group.first], group);
            object.modelview = frameBatches[group.first].modelview;
            object.firstBatch = group.first;
            object.batchCount = group.count;
            out.push_back(std::move(object));
        }
    } catch (...) {
        // Only std::bad_alloc gets here; the cache holds no half-updated mesh (obtain()).
        ++mCounters.failures;
    }
}

CacheStats Reconstructor::cacheStats() const
{
    CacheStats stats = mCounters;
    stats.entries = mCache.entries();
    stats.bytes = mCache.bytes();
    stats.budgetBytes = mCache.budget();
    return stats;
}

void Reconstructor::clearCache() noexcept
{
    mCache.clear();
}

void Reconstructor::setCacheBudget(size_t bytes) noexcept
{
    mCache.setBudget(bytes);
    mCounters.evictions += mCache.trim();
}

void Reconstructor::setParams(const ReconstructParams& params) noexcept
{
    mParams = sanitized(params);
    mCache.clear();
}

} // namespace nprgl::reconstruct
