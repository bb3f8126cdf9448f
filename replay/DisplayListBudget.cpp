#include "replay/DisplayListBudget.h"

#include <GL/gl.h>

#include <algorithm>

namespace nprgl {

namespace {

uint64_t addSat(uint64_t a, uint64_t b)
{
    return std::min(a + std::min(b, DisplayListBudget::kSaturated), DisplayListBudget::kSaturated);
}

uint64_t mulSat(uint64_t a, uint64_t b)
{
    if (a == 0 || b == 0) return 0;
    return a > DisplayListBudget::kSaturated / b ? DisplayListBudget::kSaturated : a * b;
}

} // namespace

void DisplayListBudget::newList(uint32_t list, uint32_t mode)
{
    // A superset of what the driver accepts: counting calls it does not compile only
    // overestimates.
    if (mCompiling || list == 0 || (mode != GL_COMPILE && mode != GL_COMPILE_AND_EXECUTE)) return;
    mCompiling = true;
    mExecuteToo = mode == GL_COMPILE_AND_EXECUTE;
    mCurrent = list;
    mNew = List{};
}

void DisplayListBudget::endList()
{
    if (!mCompiling) return;
    mCompiling = false;
    mExecuteToo = false;
    mLists[mCurrent] = std::move(mNew);
    mNew = List{};
    mDirty = true;
}

void DisplayListBudget::addWork(uint64_t work)
{
    if (mCompiling) mNew.own = addSat(mNew.own, work);
}

void DisplayListBudget::addCall(uint32_t list)
{
    if (mCompiling) mNew.calls.push_back(list);
}

void DisplayListBudget::addCalls(uint64_t n)
{
    if (mCompiling) mNew.wild = addSat(mNew.wild, n);
}

void DisplayListBudget::deleteLists(uint32_t list, uint64_t range)
{
    // Over the lists we know, not over the range (which may be huge).
    for (auto it = mLists.begin(); it != mLists.end();) {
        if (it->first >= list && it->first - list < range) {
            it = mLists.erase(it);
            mDirty = true;
        } else {
            ++it;
        }
    }
}

void DisplayListBudget::update()
{
    if (!mDirty) return;
    mDirty = false;
    // cost_d(l) = own + sum of cost_{d-1} of the lists it calls (+ wild * max cost_{d-1}),
    // iterated to the nesting limit or until nothing changes (no cycle).
    std::unordered_map<uint32_t, uint64_t> prev, next;
    uint64_t prevMax = 0;
    for (int depth = 1; depth <= kNestingLimit + 1; ++depth) {
        uint64_t nextMax = 0;
        next.clear();
        for (const auto& [id, list] : mLists) {
            uint64_t c = addSat(list.own, mulSat(list.wild, prevMax));
            for (uint32_t callee : list.calls) {
                auto it = prev.find(callee);
                c = addSat(c, 1 + (it == prev.end() ? 0 : it->second));
            }
            next[id] = c;
            nextMax = std::max(nextMax, c);
            mOverhead += 1 + list.calls.size();
        }
        const bool same = next == prev;
        prev.swap(next);
        prevMax = nextMax;
        if (same) break;
    }
    mCost.swap(prev);
    mMaxCost = prevMax;
}

uint64_t DisplayListBudget::cost(uint32_t list)
{
    update();
    auto it = mCost.find(list);
    return 1 + (it == mCost.end() ? 0 : it->second);
}

uint64_t DisplayListBudget::costOfCalls(uint64_t n)
{
    update();
    return addSat(n, mulSat(n, mMaxCost));
}

uint64_t DisplayListBudget::takeOverhead()
{
    uint64_t o = mOverhead;
    mOverhead = 0;
    return o;
}

} // namespace nprgl
