#pragma once

#include <cstddef>
#include <cstdint>

namespace nprgl {

class Context;
class Recorder;

// Where a Recorder's Stream goes, frame by frame: the capture file, or the live exporter.
// Called per frame and per blob, never per vertex.
class StreamSink {
public:
    virtual ~StreamSink() = default;
    // Stores a blob (once) and returns its hash.
    virtual uint64_t putBlob(const Context& ctx, const void* data, size_t size) = 0;
    // Takes one complete frame; false when the sink wants no more frames.
    virtual bool writeFrame(const Context& ctx, uint64_t frame, const uint8_t* calls,
                            size_t size) = 0;
    virtual void addUncaptured(const char* name, uint64_t count) = 0;
    virtual void attach(Recorder*) {}
    virtual void detach(Recorder*) {}
};

} // namespace nprgl
