// LiveVideo: a live run's frames sent to the `nprgl run --video` process that encodes them.
#pragma once

#include "common/VideoFeed.h"
#include "shim/Context.h"

#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <string>
#include <vector>

namespace nprgl {

// The program's side of `nprgl run --video`: at a frame's end the window's picture is read
// into a buffer and a thread of its own sends it over a local socket to the nprgl process,
// which encodes it (FFmpeg is never loaded into the program). The program never waits for the
// encoder: while a frame is still being sent the next ones are not read, and counted. The
// video key stops the recording and starts the next one (the next file). One context of one
// process is recorded: the first to end a frame; the others are said once.
class LiveVideo {
public:
    // The process's feed when `nprgl run --video` asked for one (NPRGL_VIDEO_SOCKET), else
    // null. A process forked from one that sent frames gets its own (its own connection).
    static LiveVideo* instance();

    // At a frame's end: whether context `serial`'s frame is to be read now (a recording is on,
    // this is the recorded context and the previous frame has gone).
    bool wants(uint32_t serial);
    // Reads and queues the frame wants() asked for.
    void addFrame(uint32_t serial, uint64_t frame, const ContextCaps& caps, int width,
                  int height);
    // The video key: stop the recording, or start the next one.
    void toggle(uint32_t serial);

private:
    LiveVideo(std::string socketName, bool waitForKey, int fps);
    void sendLoop();
    // Connects and says hello; false (said once) when nprgl is not there or refuses.
    bool connectToReceiver();
    // The process ends: the frame being sent, and the one queued, still go (a bounded wait).
    void flushAtExit();

    std::string mSocketName;
    int mSocket = -1;

    std::mutex mMutex;
    std::condition_variable mChanged;
    bool mRecording = false;
    bool mStopped = false;   // the connection failed or was refused: no more frames
    uint32_t mContext = 0;   // the recorded context's serial; 0 until the first frame
    uint32_t mSpan = 0;
    uint64_t mDropped = 0;
    // The video's clock: a frame is read when its time is in a video frame after the last
    // one read (a program faster than the video has most of its frames never read).
    uint64_t mPeriodNs = 0;
    uint64_t mSpanStartNs = 0; // the recording's first frame; 0: none yet
    uint64_t mLastSlot = 0;
    uint64_t mWantedNs = 0;    // when wants() said yes: the frame's time
    bool mOtherSaid = false;
    bool mUnreadableSaid = false;
    bool mThreadStarted = false;
    // One frame queued (mQueued) while the thread sends the previous one from mSending.
    video::FrameHeader mQueuedHeader;
    std::vector<uint8_t> mQueued;
    bool mQueuedFull = false;
    bool mSendingBusy = false;
    std::vector<uint8_t> mSending;
};

} // namespace nprgl
