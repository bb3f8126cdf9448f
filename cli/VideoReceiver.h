// VideoReceiver: `nprgl run --video`'s side of the feed: frames from the program, paced to the
// clock and encoded into one file per recording.
#pragma once

#include "common/PngImage.h"
#include "common/VideoFeed.h"
#include "replay/VideoWriter.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace nprgl::cli {

// Listens on a local socket (an abstract name, this user's processes only) while the program
// runs. The first process of the run that sends a frame is the one recorded; one that
// connects meanwhile is refused and says so. Frames are placed on the video's clock by when
// they were read: a frame the program did not draw in time (or that was not taken while the
// encoder was busy) is the one before it again, so the video plays at the program's speed.
// Each recording the video key starts is the next file: FILE, then <stem>-2<ext>, ...
class VideoReceiver {
public:
    VideoReceiver();
    ~VideoReceiver();

    // Checks FILE and the rate as `nprgl replay --video` does, and starts listening; false
    // with a one-line reason.
    bool open(const std::string& path, int fps, std::string& error);
    // The name the program's library connects to (NPRGL_VIDEO_SOCKET).
    const std::string& socketName() const { return mSocketName; }
    // Accepts connections and takes frames for up to timeoutMs.
    void serve(int timeoutMs);
    // The program ended: takes what is still on its way (a bounded wait), finishes the file
    // and says what was written.
    void finish();

private:
    struct Connection;
    void accept();
    // Reads one message from the recorded process; false when it ended or sent damage.
    bool readFrame();
    void takeFrame(const video::FrameHeader& header, uint32_t pid);
    void startFile();
    void endFile();
    void emit();
    std::string fileName(uint32_t index) const;

    std::string mPath;
    int mFps = 30;
    std::string mSocketName;
    int mListen = -1;
    std::unique_ptr<Connection> mActive;

    // The file being written.
    std::unique_ptr<VideoWriter> mWriter;
    uint32_t mFiles = 0;
    uint32_t mSpan = 0;          // the recording (span) it holds
    uint32_t mPid = 0;           // of the process that drew it
    uint64_t mStartNs = 0;       // the first frame's time
    uint64_t mEmitted = 0;       // video frames written: the next one is at mStartNs + n/fps
    uint64_t mTaken = 0;         // frames of the program in it
    uint64_t mFirstFrame = 0;
    uint64_t mLastFrame = 0;
    uint64_t mDroppedBefore = 0; // the sender's count when the file began
    uint64_t mDropped = 0;
    bool mLastEmitted = false;
    bool mFailed = false;        // the encoder failed: the rest of this recording is skipped
    bool mResizeSaid = false;
    PngImage mLast;              // the latest frame, top row first, at the file's size
    std::vector<uint8_t> mPixels;
};

} // namespace nprgl::cli
