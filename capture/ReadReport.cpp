#include "capture/ReadReport.h"

#include <algorithm>
#include <map>
#include <set>

namespace nprgl::capture {

namespace {

// Ranges listed per context before the rest is summed up.
constexpr size_t kRangesShown = 8;

} // namespace

void ReadReport::frameLost(size_t index)
{
    if (index >= mReader.frames().size()) return;
    const CaptureReader::FrameInfo& f = mReader.frames()[index];
    mLost.push_back(CaptureReader::FrameId{f.contextId, f.frameNumber});
}

bool ReadReport::damaged() const
{
    return !mReader.damage().empty() || !mReader.missingFrames().empty() || !mLost.empty();
}

std::vector<CaptureReader::FrameId> ReadReport::lostFrames() const
{
    std::vector<CaptureReader::FrameId> all = mReader.missingFrames();
    for (const CaptureReader::FrameId& id : mLost)
        if (std::find(all.begin(), all.end(), id) == all.end()) all.push_back(id);
    return all;
}

std::string ReadReport::summary(uint64_t framesRead) const
{
    if (!damaged()) return {};
    const std::vector<CaptureReader::FrameId> lost = lostFrames();
    std::string line = mReader.path() + ": damaged";
    if (framesRead != kUnknown) {
        line += ": " + std::to_string(framesRead) + " frame" + (framesRead == 1 ? "" : "s") +
                " read";
    }
    // Without an index, frames lost after a context's last readable one leave no trace.
    const bool exact = mReader.knowsAllFrames() || mReader.damage().empty();
    const std::string comma = framesRead == kUnknown ? ": " : ", ";
    if (lost.empty()) {
        line += exact ? comma + "no frame lost"
                      : "; frames lost in the damaged bytes cannot be counted (no index)";
    } else {
        line += comma + (exact ? "" : "at least ") + std::to_string(lost.size()) + " lost (" +
                describe(lost) + ")";
    }
    if (uint64_t blobs = mReader.missingBlobs()) {
        line += "; " + std::to_string(blobs) + " blob" + (blobs == 1 ? "" : "s") +
                " lost (frames that draw with " + (blobs == 1 ? "it" : "them") +
                " cannot be read)";
    }
    return line;
}

std::string ReadReport::describe(const std::vector<CaptureReader::FrameId>& frames)
{
    std::map<uint32_t, std::set<uint64_t>> byContext;
    for (const CaptureReader::FrameId& id : frames) byContext[id.contextId].insert(id.frameNumber);
    std::string out;
    for (const auto& [context, numbers] : byContext) {
        out += (out.empty() ? "" : "; ") + std::string("context ") + std::to_string(context) +
               ": ";
        size_t ranges = 0, rest = 0;
        for (auto it = numbers.begin(); it != numbers.end();) {
            uint64_t first = *it, last = first;
            for (++it; it != numbers.end() && *it == last + 1; ++it) last = *it;
            if (ranges++ >= kRangesShown) {
                rest += last - first + 1;
                continue;
            }
            out += (ranges > 1 ? ", " : "") + std::to_string(first) +
                   (last > first ? "-" + std::to_string(last) : "");
        }
        if (rest > 0) out += " and " + std::to_string(rest) + " more";
    }
    return out;
}

} // namespace nprgl::capture
