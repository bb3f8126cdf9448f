#pragma once

// DisplayListBudget: an upper bound of the work glCallList/glCallLists run in a replayed
// stream, so a hostile one cannot make the driver loop for ever (lists calling lists).

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace nprgl {

// Follows list compilation from the decoded calls and bounds what executing a list costs:
// its own calls (weighted by the vertices they draw) plus, to the driver's nesting limit,
// the lists it calls. A glCallLists inside a list counts as calls of the costliest list,
// whatever list base is current when it runs. Overestimates are fine; underestimates not.
class DisplayListBudget {
public:
    static constexpr uint64_t kSaturated = uint64_t(1) << 62;
    static constexpr int kNestingLimit = 64; // Mesa's MAX_LIST_NESTING

    // glNewList / glEndList, as the decoder sees them (mode: GL_COMPILE...).
    void newList(uint32_t list, uint32_t mode);
    void endList();
    bool compiling() const { return mCompiling; }
    // True when calls now run (not only compiled into a list).
    bool executing() const { return !mCompiling || mExecuteToo; }
    // The current call's work, when it is compiled into the list being defined.
    void addWork(uint64_t work);
    // Calls compiled into the list being defined.
    void addCall(uint32_t list);
    void addCalls(uint64_t n);
    void deleteLists(uint32_t list, uint64_t range);
    // The work of executing list now, or of n lists of glCallLists.
    uint64_t cost(uint32_t list);
    uint64_t costOfCalls(uint64_t n);
    // Work spent on bookkeeping since the last call (recomputing costs), to charge a budget.
    uint64_t takeOverhead();

private:
    struct List {
        uint64_t own = 0;
        uint64_t wild = 0; // glCallLists entries
        std::vector<uint32_t> calls;
    };
    void update();

    std::unordered_map<uint32_t, List> mLists;
    std::unordered_map<uint32_t, uint64_t> mCost;
    uint64_t mMaxCost = 0;
    bool mDirty = false;
    bool mCompiling = false;
    bool mExecuteToo = false;
    uint32_t mCurrent = 0;
    List mNew;
    uint64_t mOverhead = 0;
};

} // namespace nprgl
