#pragma once

#include "common/FrameSet.h"
#include "frame/StateTracker.h"
#include "frame/StreamSink.h"
#include "reconstruct/Reconstructor.h"

#include <map>
#include <mutex>
#include <string>
#include <vector>

namespace nprgl {

// NPRGL_EXPORT="frame=N;dir=D": the running program's frame N, reconstructed and written as
// D/<program>_<N>.obj (HijackGL's "3D screenshot"). The stream of the first context is
// interpreted as it is recorded (in memory) up to that frame.
class LiveExport : public StreamSink {
public:
    // Null unless NPRGL_EXPORT asks for an export (and the process is not recording).
    static LiveExport* instance();

    uint64_t putBlob(const Context& ctx, const void* data, size_t size) override;
    bool writeFrame(const Context& ctx, uint64_t frame, const uint8_t* calls,
                    size_t size) override;
    void addUncaptured(const char*, uint64_t) override {}

private:
    class Blobs : public BlobSource {
    public:
        const std::vector<uint8_t>* blob(uint64_t hash, std::string& error) override;
        std::map<uint64_t, std::vector<uint8_t>> stored;
    };

    LiveExport(FrameSet frames, std::string dir, std::string format);

    std::mutex mMutex;
    FrameSet mFrames;
    std::string mDir;
    std::string mFormat;
    uint32_t mContext = 0; // the context whose frames are exported (the first to draw)
    bool mDone = false;
    Blobs mBlobs;
    StateTracker mTracker;
    reconstruct::Reconstructor mReconstructor;
};

} // namespace nprgl
