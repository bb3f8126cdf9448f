#include "reconstruct/MeshCache.h"

#include <algorithm>

namespace nprgl::reconstruct {

MeshCache::Entry* MeshCache::find(uint64_t contentKey)
{
    const auto it = mByContent.find(contentKey);
    if (it == mByContent.end()) return nullptr;
    mLru.splice(mLru.begin(), mLru, it->second);
    return &*it->second;
}

void MeshCache::findStructure(uint64_t structureKey, std::vector<Entry*>& out)
{
    out.clear();
    const auto range = mByStructure.equal_range(structureKey);
    for (auto it = range.first; it != range.second; ++it) out.push_back(&*it->second);
    std::sort(out.begin(), out.end(),
              [](const Entry* a, const Entry* b) { return a->lastFrame > b->lastFrame; });
}

MeshCache::Entry* MeshCache::insert(uint64_t contentKey, uint64_t structureKey,
                                    std::shared_ptr<ObjectMesh> mesh)
{
    Entry entry;
    entry.contentKey = contentKey;
    entry.structureKey = structureKey;
    entry.bytes = mesh->byteSize();
    entry.mesh = std::move(mesh);
    mLru.push_front(std::move(entry));
    const Iterator it = mLru.begin();
    // Exception-safe: a failed index insertion leaves the cache as it was.
    try {
        mByContent.emplace(contentKey, it);
        try {
            mByStructure.emplace(structureKey, it);
        } catch (...) {
            mByContent.erase(contentKey);
            throw;
        }
    } catch (...) {
        mLru.erase(it);
        throw;
    }
    mBytes += it->bytes;
    return &*it;
}

void MeshCache::rekey(Entry* entry, uint64_t contentKey)
{
    const auto old = mByContent.find(entry->contentKey);
    const Iterator it = old->second;
    mByContent.emplace(contentKey, it); // first: if it throws, nothing has changed
    mByContent.erase(old);
    entry->contentKey = contentKey;
    mBytes -= entry->bytes;
    entry->bytes = entry->mesh->byteSize();
    mBytes += entry->bytes;
    mLru.splice(mLru.begin(), mLru, it);
}

void MeshCache::eraseStructure(Iterator it) noexcept
{
    const auto range = mByStructure.equal_range(it->structureKey);
    for (auto s = range.first; s != range.second; ++s) {
        if (s->second == it) {
            mByStructure.erase(s);
            return;
        }
    }
}

void MeshCache::erase(Entry* entry) noexcept
{
    const auto found = mByContent.find(entry->contentKey);
    if (found == mByContent.end() || &*found->second != entry) return;
    const Iterator it = found->second;
    mByContent.erase(found);
    eraseStructure(it);
    mBytes -= it->bytes;
    mLru.erase(it);
}

size_t MeshCache::trim()
{
    size_t evicted = 0;
    while (mBytes > mBudget && !mLru.empty()) {
        erase(&mLru.back());
        ++evicted;
    }
    return evicted;
}

void MeshCache::clear()
{
    mByContent.clear();
    mByStructure.clear();
    mLru.clear();
    mBytes = 0;
}

} // namespace nprgl::reconstruct
