#pragma once

#include <cstddef>
#include <cstdint>
#include <list>
#include <memory>
#include <unordered_map>
#include <vector>

#include "reconstruct/ObjectMesh.h"

namespace nprgl::reconstruct {

struct CacheStats {
    uint64_t hits = 0;      // objects whose batches were unchanged: returned as cached
    uint64_t updates = 0;   // same topology, moved vertices: connectivity kept
    uint64_t rebuilds = 0;  // built from scratch: new, or changed topology
    uint64_t evictions = 0; // entries dropped to stay within the budget
    uint64_t failures = 0;  // frames that ran out of memory (their objects are missing)
    size_t entries = 0;
    size_t bytes = 0;
    size_t budgetBytes = 0;
};

// Reconstructed meshes by the content key of their batches, with a second index by structure
// key (batch modes and vertex counts) to find a mesh that an animated object can update.
// Bounded by bytes; the least recently used entry goes first. Not thread-safe.
class MeshCache {
public:
    struct Entry {
        uint64_t contentKey = 0;
        uint64_t structureKey = 0;
        std::shared_ptr<ObjectMesh> mesh;
        size_t bytes = 0;
        uint64_t lastFrame = 0;
    };

    explicit MeshCache(size_t budgetBytes) : mBudget(budgetBytes) {}

    // Marks a found entry most recently used.
    Entry* find(uint64_t contentKey);
    // Entries with this structure key, most recently used first.
    void findStructure(uint64_t structureKey, std::vector<Entry*>& out);
    Entry* insert(uint64_t contentKey, uint64_t structureKey, std::shared_ptr<ObjectMesh> mesh);
    // After an update: the entry now shows other content and may have another size; marks it
    // most recently used.
    void rekey(Entry* entry, uint64_t contentKey);
    void erase(Entry* entry) noexcept;
    // Evicts least recently used entries until the total is within the budget (an entry
    // larger than the whole budget is not kept either). Returns how many went.
    size_t trim();
    void clear();

    size_t bytes() const { return mBytes; }
    size_t entries() const { return mLru.size(); }
    size_t budget() const { return mBudget; }
    void setBudget(size_t budgetBytes) { mBudget = budgetBytes; }

private:
    using Iterator = std::list<Entry>::iterator;
    void eraseStructure(Iterator it) noexcept;

    std::list<Entry> mLru; // front: most recently used
    std::unordered_map<uint64_t, Iterator> mByContent;
    std::unordered_multimap<uint64_t, Iterator> mByStructure;
    size_t mBytes = 0;
    size_t mBudget;
};

} // namespace nprgl::reconstruct
