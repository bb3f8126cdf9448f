#pragma once

#include "capture/CaptureWriter.h"
#include "capture/Metadata.h"
#include "common/FrameSet.h"
#include "frame/StreamSink.h"

#include <cstdint>
#include <mutex>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace nprgl {


// The process's capture file (NPRGL_RECORD): opened when the first recording context becomes
// current, written at every frame end, closed with its index at exit. A forked child that
// records opens its own file, `<name>.<pid>.nprgl`, never the parent's.
class CaptureSession : public StreamSink {
public:
    // Null when the process is not recording.
    static CaptureSession* instance();

    // Opens the file first if needed (blobs come before the first frame that uses them).
    uint64_t putBlob(const Context& ctx, const void* data, size_t size) override;
    // Writes one frame of a context if it is inside the recorded range (frames before the
    // range are kept too: they create the lists, textures and buffers later frames use).
    // Returns false once the range is over: recording stops.
    bool writeFrame(const Context& ctx, uint64_t frame, const uint8_t* calls,
                    size_t size) override;
    void addUncaptured(const char* name, uint64_t count) override;
    // Recorders report their counts at each frame end; at exit the session asks the ones
    // still alive for the rest.
    void attach(Recorder* recorder) override;
    void detach(Recorder* recorder) override;

    // Closes the file with its index and reports what was not captured.
    void finish();

private:
    CaptureSession(std::string path, FrameSet frames);
    bool ensureOpenLocked(const Context& ctx);
    void finishLocked();
    void addUncapturedLocked(const char* name, uint64_t count);

    std::mutex mMutex;
    std::string mBasePath;
    std::string mPath;
    FrameSet mFrames;
    uint64_t mLastFrame;
    capture::CaptureWriter mWriter;
    capture::Metadata mMeta; // as the header has it
    // Each context's drawable size at its last frame written (to say when it changes).
    std::unordered_map<uint32_t, std::pair<int, int>> mShownSizes;
    bool mOpenFailed = false;
    bool mFinished = false; // closed with its index: later frames are not recorded
    uint64_t mFramesWritten = 0;
    std::vector<std::pair<std::string, uint64_t>> mUncaptured;
    std::vector<Recorder*> mRecorders;
    bool mUncapturedChanged = false;
};

} // namespace nprgl
