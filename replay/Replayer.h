#pragma once

#include "capture/CaptureReader.h"
#include "capture/ReadReport.h"
#include "common/FrameSet.h"
#include "common/PngImage.h"
#include "replay/ReplayLimits.h"
#include "shim/Config.h"

#include <functional>
#include <optional>
#include <string>

namespace nprgl {

struct ReplayOptions {
    std::string outDir;    // PNGs frame_0000000042.png; empty: render only
    FrameSet frames;       // frames to write (empty: all)
    int width = 0;         // 0: the recorded size
    int height = 0;
    uint32_t contextId = 0; // 0: the stream with the most frames
    bool progress = false;  // a progress bar on stderr
    bool stats = false;     // each frame's 3D draws and what it cleared to, on stdout
    bool overlays = false;  // with stats: each frame's 2D draws and their contrast
    ReplayLimits limits;    // what a call may ask of the driver before it is refused
    // The style and values to replay with; unset: the process's (the environment's).
    std::optional<Config> config;
    // Also given each selected frame's picture (a video's next frame); false stops the replay
    // with its error.
    std::function<bool(const PngImage&, std::string& error)> onFrame;
};

// Replays a capture headless on OSMesa through the same pipeline the library runs inside an
// application (the context's dispatch table), writing the frames as PNG.
class Replayer {
public:
    // Returns false with a one-line message on bad input, naming the file, the frame and the
    // call (its index in the frame, from 0): a malformed call, or one the driver would trust
    // and crash or hang on (see ReplaySink).
    static bool run(const std::string& path, const ReplayOptions& options, std::string& error,
                    uint64_t* framesWritten = nullptr);
    // The same on an open reader. With a report, a frame whose chunk does not read is logged,
    // noted in it and skipped (the frames after it may then differ from the recording's).
    static bool run(const capture::CaptureReader& reader, const ReplayOptions& options,
                    std::string& error, uint64_t* framesWritten, capture::ReadReport* report);
    // The stream replayed when none is chosen: the context with the most frames.
    static uint32_t defaultContext(const capture::CaptureReader& reader);
};

} // namespace nprgl
