// A process that speaks to `nprgl run --video` as a damaged or hostile library would: the
// receiver's checks of what comes over its socket, without GL. Modes: --not-nprgl (a hello
// that is not one), --bad-magic (a frame header that is not one), --huge (a frame larger
// than any video), --truncated (a frame that ends half-way), --good N (N small frames, each
// a grey level of its own, 40 ms apart on the clock they carry).
#include "common/SocketIo.h"
#include "common/VideoFeed.h"

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unistd.h>
#include <vector>

using namespace nprgl;

namespace {

int connectFeed()
{
    const char* name = std::getenv(video::kSocketVariable);
    if (!name) {
        std::fprintf(stderr, "probe_video_feed: no %s\n", video::kSocketVariable);
        std::exit(3);
    }
    const int fd = SocketIo::connectAbstract(name);
    if (fd < 0) std::exit(4);
    return fd;
}

void sendAll(int fd, const void* data, size_t bytes)
{
    if (!SocketIo::sendAll(fd, data, bytes)) std::exit(5);
}

void hello(int fd)
{
    video::Hello h;
    h.pid = uint32_t(getpid());
    sendAll(fd, &h, sizeof h);
    char answer = 0;
    if (!SocketIo::readAll(fd, &answer, 1) || answer != video::kAccepted) std::exit(6);
}

video::FrameHeader header(uint32_t width, uint32_t height, uint64_t frame)
{
    video::FrameHeader h;
    h.span = 1;
    h.width = width;
    h.height = height;
    h.timeNs = frame * 40000000ull;
    h.frame = frame;
    return h;
}

} // namespace

int main(int argc, char** argv)
{
    const std::string mode = argc > 1 ? argv[1] : "";
    const int fd = connectFeed();
    if (mode == "--not-nprgl") {
        const char text[] = "GET / HTTP/1.0\r\n\r\n";
        sendAll(fd, text, sizeof text - 1);
        return 0;
    }
    hello(fd);
    if (mode == "--bad-magic") {
        video::FrameHeader h = header(8, 8, 1);
        sendAll(fd, &h, sizeof h);
        std::vector<uint8_t> pixels(8 * 8 * 4, 128);
        sendAll(fd, pixels.data(), pixels.size());
        h.magic = 0x12345678;
        sendAll(fd, &h, sizeof h);
    } else if (mode == "--huge") {
        video::FrameHeader h = header(100000, 100000, 1);
        sendAll(fd, &h, sizeof h);
    } else if (mode == "--truncated") {
        video::FrameHeader h = header(64, 64, 1);
        sendAll(fd, &h, sizeof h);
        std::vector<uint8_t> pixels(64 * 32 * 4, 200);
        sendAll(fd, pixels.data(), pixels.size());
    } else if (mode == "--good" && argc > 2) {
        const int frames = std::atoi(argv[2]);
        for (int i = 1; i <= frames; ++i) {
            video::FrameHeader h = header(32, 32, uint64_t(i));
            sendAll(fd, &h, sizeof h);
            std::vector<uint8_t> pixels(32 * 32 * 4, uint8_t(i * 40));
            sendAll(fd, pixels.data(), pixels.size());
        }
    } else {
        std::fprintf(stderr, "probe_video_feed: unknown mode %s\n", mode.c_str());
        return 2;
    }
    return 0;
}
