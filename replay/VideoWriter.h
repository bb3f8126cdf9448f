#pragma once

// VideoWriter: frames (RGBA, top row first) encoded into a video file with Debian's FFmpeg
// libraries: H.264 (libx264) in .mp4, .mkv or .mov, VP9 (libvpx) in .webm.

#include <cstdint>
#include <memory>
#include <string>

namespace nprgl {

struct PngImage;

class VideoWriter {
public:
    VideoWriter();
    ~VideoWriter();
    VideoWriter(const VideoWriter&) = delete;
    VideoWriter& operator=(const VideoWriter&) = delete;

    // Quality: a replay's, which may take its time. Live: a running program's, encoded beside
    // it on the same processors, at a screen recorder's speed (x264 veryfast, VP9 realtime).
    enum class Speed { Quality, Live };

    // Checks that `path` names a container this FFmpeg writes (by its extension) with an
    // encoder for it, before any frame is rendered. False with a one-line reason.
    bool open(const std::string& path, int fps, std::string& error,
              Speed speed = Speed::Quality);
    // Encodes the next frame; the first one sets the video's size (4:2:0 video needs an even
    // size: an odd width or height loses its last column or row) and creates the file.
    bool add(const PngImage& image, std::string& error);
    // Flushes the encoder and writes the file's index; a writer not finished leaves a file
    // that players may refuse.
    bool finish(std::string& error);
    uint64_t frames() const { return mFrames; }

private:
    struct State;
    bool start(int width, int height, std::string& error);
    bool encode(bool flush, std::string& error);

    std::unique_ptr<State> mState;
    uint64_t mFrames = 0;
};

} // namespace nprgl
