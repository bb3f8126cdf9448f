#include "frame/DrawCounts.h"

#include <algorithm>

namespace nprgl {

bool DrawCounts::noteLeft(const char* why)
{
    auto seen = std::find_if(mLeft.begin(), mLeft.end(),
                             [why](const auto& entry) { return entry.first == why; });
    if (seen != mLeft.end()) {
        ++seen->second;
        return false;
    }
    mLeft.emplace_back(why, 1);
    return true;
}

void DrawCounts::clear()
{
    mStyled = 0;
    mMerged = 0;
    for (auto& entry : mLeft) entry.second = 0; // keeps the reasons: no allocation per frame
}

DrawCounts DrawCounts::since(const DrawCounts& earlier) const
{
    DrawCounts d = *this;
    d.mStyled -= std::min(earlier.mStyled, mStyled);
    d.mMerged -= std::min(earlier.mMerged, mMerged);
    for (auto& [why, n] : d.mLeft) {
        for (const auto& [was, m] : earlier.mLeft) {
            if (was == why) n -= std::min(m, n);
        }
    }
    return d;
}

uint64_t DrawCounts::left() const
{
    uint64_t n = 0;
    for (const auto& entry : mLeft) n += entry.second;
    return n;
}

std::string DrawCounts::describe() const
{
    std::string reasons;
    for (const auto& [why, n] : mLeft) {
        if (n == 0) continue;
        reasons += (reasons.empty() ? "" : ", ") + std::string(why) + " " + std::to_string(n);
    }
    const uint64_t leftDraws = left();
    std::string s = std::to_string(mStyled) + " styled";
    if (mMerged) s += " (" + std::to_string(mMerged) + " of them passes merged into their object)";
    s += ", " + std::to_string(leftDraws) + " left as the program drew them";
    if (leftDraws) s += " (" + reasons + ")";
    return s;
}

} // namespace nprgl
