#pragma once

// What reading a capture found wrong, said the same way by every command that reads one.

#include "capture/CaptureReader.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace nprgl::capture {

// Gathers the reader's damage (found at open) and the frames a command could not read, and
// words the one-line summary a command ends with. A command says reader.notes() at open, each
// frame's error as it meets it, and summary() at the end; when damaged() it exits 1.
class ReadReport {
public:
    explicit ReadReport(const CaptureReader& reader) : mReader(reader) {}

    // Frame index (of reader.frames()) did not read.
    void frameLost(size_t index);
    // Damage found at open, or a frame that did not read.
    bool damaged() const;
    // Frames noted by frameLost.
    size_t unreadable() const { return mLost.size(); }
    static constexpr uint64_t kUnknown = UINT64_MAX;
    // "FILE: damaged: 405 frames read, 1 lost (context 1: 200)"; empty when not damaged.
    // framesRead kUnknown leaves the count out (a command that stopped early).
    std::string summary(uint64_t framesRead) const;
    // Every frame known lost, at open and since.
    std::vector<CaptureReader::FrameId> lostFrames() const;
    // "context 1: 3-5, 9; context 2: 4", at most a few ranges per context.
    static std::string describe(const std::vector<CaptureReader::FrameId>& frames);

private:
    const CaptureReader& mReader;
    std::vector<CaptureReader::FrameId> mLost;
};

} // namespace nprgl::capture
