#include "common/FrameSet.h"

#include <algorithm>
#include <charconv>

namespace nprgl {

namespace {

bool parseNumber(std::string_view text, uint64_t& out)
{
    if (text.empty()) return false;
    auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
    return ec == std::errc() && ptr == text.data() + text.size();
}

} // namespace

bool FrameSet::parse(std::string_view text, FrameSet& out, std::string& error)
{
    FrameSet set;
    while (!text.empty()) {
        size_t comma = text.find(',');
        std::string_view item = text.substr(0, comma);
        text = comma == std::string_view::npos ? std::string_view() : text.substr(comma + 1);
        size_t dash = item.find('-');
        Range range{};
        bool ok = dash == std::string_view::npos
                      ? parseNumber(item, range.first) && (range.last = range.first, true)
                      : parseNumber(item.substr(0, dash), range.first) &&
                            (dash + 1 == item.size()
                                 ? (range.last = UINT64_MAX, true)
                                 : parseNumber(item.substr(dash + 1), range.last));
        if (!ok || range.first == 0 || range.last < range.first) {
            error = "bad frame list item '" + std::string(item) +
                    "' (expected N, A-B or A-, frames counted from 1)";
            return false;
        }
        set.mRanges.push_back(range);
    }
    if (set.mRanges.empty()) {
        error = "empty frame list";
        return false;
    }
    out = std::move(set);
    return true;
}

bool FrameSet::contains(uint64_t frame) const
{
    return std::any_of(mRanges.begin(), mRanges.end(),
                       [frame](const Range& r) { return frame >= r.first && frame <= r.last; });
}

uint64_t FrameSet::last() const
{
    uint64_t last = 0;
    for (const Range& r : mRanges) last = std::max(last, r.last);
    return last;
}

std::string FrameSet::describe(const std::vector<uint64_t>& frames)
{
    std::string out;
    for (size_t i = 0; i < frames.size();) {
        size_t j = i;
        while (j + 1 < frames.size() && frames[j + 1] == frames[j] + 1) ++j;
        out += (out.empty() ? "" : ",") + std::to_string(frames[i]);
        if (j > i) out += "-" + std::to_string(frames[j]);
        i = j + 1;
    }
    return out;
}

} // namespace nprgl
