// VideoFeed: the messages a program's library sends `nprgl run --video` over a local socket.
#pragma once

#include <cstdint>

namespace nprgl::video {

// The environment of a program `nprgl run --video` started: the socket's abstract name
// (without the leading NUL), "key" when the first recording waits for the video key, and the
// video's frame rate (a frame is read only when the video's clock has moved on to a new frame).
inline constexpr const char* kSocketVariable = "NPRGL_VIDEO_SOCKET";
inline constexpr const char* kStartVariable = "NPRGL_VIDEO_START";
inline constexpr const char* kFpsVariable = "NPRGL_VIDEO_FPS";

inline constexpr uint32_t kHelloMagic = 0x4f44564eu; // "NVDO"
inline constexpr uint32_t kFrameMagic = 0x4d52464eu; // "NFRM"
inline constexpr uint32_t kVersion = 1;

// Sent once after connecting; the answer is one byte: kAccepted, or kRefused when another
// process of the run is being recorded.
struct Hello {
    uint32_t magic = kHelloMagic;
    uint32_t version = kVersion;
    uint32_t pid = 0;
    uint32_t reserved = 0;
};
inline constexpr char kAccepted = 'Y';
inline constexpr char kRefused = 'N';

// One frame: this header, then width * height RGBA pixels, bottom row first (as glReadPixels
// reads them). `span` counts the recordings the video key started: a new span is a new file.
struct FrameHeader {
    uint32_t magic = kFrameMagic;
    uint32_t span = 0;
    uint32_t width = 0;
    uint32_t height = 0;
    uint64_t timeNs = 0;   // CLOCK_MONOTONIC when the frame was read
    uint64_t frame = 0;    // the context's frame number
    uint64_t dropped = 0;  // frames not read so far because the previous one was still sent
};

// Frames larger than this are refused by the receiver as damage, not allocated.
inline constexpr uint32_t kMaxSide = 16384;

} // namespace nprgl::video
