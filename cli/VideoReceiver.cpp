#include "cli/VideoReceiver.h"

#include "common/SocketIo.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <poll.h>
#include <random>
#include <sys/socket.h>
#include <unistd.h>
#include <utility>

namespace nprgl::cli {

namespace {

// Waits up to timeoutMs for fd to have something to read.
bool readable(int fd, int timeoutMs)
{
    pollfd p {fd, POLLIN, 0};
    int ready;
    do {
        ready = poll(&p, 1, timeoutMs);
    } while (ready < 0 && errno == EINTR);
    return ready > 0;
}

double seconds(uint64_t frames, int fps) { return double(frames) / double(fps); }

} // namespace

struct VideoReceiver::Connection {
    int fd = -1;
    uint32_t pid = 0;
    uint64_t bytes = 0; // read so far: where damage is, when there is some
    ~Connection()
    {
        if (fd >= 0) close(fd);
    }
};

VideoReceiver::VideoReceiver() = default;

VideoReceiver::~VideoReceiver()
{
    if (mListen >= 0) close(mListen);
}

bool VideoReceiver::open(const std::string& path, int fps, std::string& error)
{
    VideoWriter check;
    if (!check.open(path, fps, error)) return false;
    mPath = path;
    mFps = fps;
    std::random_device random;
    char name[64];
    std::snprintf(name, sizeof name, "nprgl-video-%d-%08x%08x", int(getpid()), random(),
                  random());
    mSocketName = name;
    mListen = SocketIo::listenAbstract(mSocketName, 8);
    if (mListen < 0) {
        error = std::string("cannot listen for the program's frames: ") + std::strerror(errno);
        return false;
    }
    return true;
}

void VideoReceiver::serve(int timeoutMs)
{
    pollfd fds[2] = {{mListen, POLLIN, 0}, {mActive ? mActive->fd : -1, POLLIN, 0}};
    if (poll(fds, 2, timeoutMs) <= 0) return;
    if (fds[0].revents & POLLIN) accept();
    if (mActive && (fds[1].revents & (POLLIN | POLLHUP | POLLERR))) {
        if (!readFrame()) mActive.reset();
    }
}

void VideoReceiver::accept()
{
    auto connection = std::make_unique<Connection>();
    connection->fd = accept4(mListen, nullptr, nullptr, SOCK_CLOEXEC);
    if (connection->fd < 0) return;
    // An abstract socket is open to every user of the machine: only this user's processes.
    ucred peer {};
    socklen_t size = sizeof peer;
    if (getsockopt(connection->fd, SOL_SOCKET, SO_PEERCRED, &peer, &size) != 0 ||
        peer.uid != getuid()) {
        return;
    }
    video::Hello hello;
    if (!readable(connection->fd, 2000) ||
        !SocketIo::readAll(connection->fd, &hello, sizeof hello) ||
        hello.magic != video::kHelloMagic || hello.version != video::kVersion) {
        std::fprintf(stderr, "nprgl: video: a connection that is not nprgl's library; "
                     "ignored\n");
        return;
    }
    connection->pid = hello.pid;
    connection->bytes = sizeof hello;
    const char answer = mActive ? video::kRefused : video::kAccepted;
    if (!SocketIo::sendAll(connection->fd, &answer, 1) || mActive) return;
    mActive = std::move(connection);
}

bool VideoReceiver::readFrame()
{
    Connection& c = *mActive;
    video::FrameHeader header;
    if (!SocketIo::readAll(c.fd, &header, sizeof header)) return false; // the process ended
    const bool sane = header.magic == video::kFrameMagic && header.span > 0 &&
                      header.width > 0 && header.height > 0 &&
                      header.width <= video::kMaxSide && header.height <= video::kMaxSide;
    if (!sane) {
        std::fprintf(stderr, "nprgl: video: a damaged frame message from process %u at byte "
                     "%llu of its feed; the rest of its frames are not in the video\n", c.pid,
                     static_cast<unsigned long long>(c.bytes));
        return false;
    }
    mPixels.resize(size_t(header.width) * header.height * 4);
    if (!SocketIo::readAll(c.fd, mPixels.data(), mPixels.size())) {
        std::fprintf(stderr, "nprgl: video: process %u ended in the middle of frame %llu; the "
                     "video ends at the frame before\n", c.pid,
                     static_cast<unsigned long long>(header.frame));
        return false;
    }
    c.bytes += sizeof header + mPixels.size();
    takeFrame(header, c.pid);
    return true;
}

void VideoReceiver::takeFrame(const video::FrameHeader& header, uint32_t pid)
{
    if (!mWriter || header.span != mSpan || pid != mPid) {
        endFile();
        mSpan = header.span;
        mPid = pid;
        mStartNs = header.timeNs;
        mDroppedBefore = header.dropped;
        mFirstFrame = header.frame;
        mLast.width = int(header.width);
        mLast.height = int(header.height);
        startFile();
    }
    if (mFailed) return;
    // The frame before fills the video's frames up to this one's time.
    const uint64_t nsPerFrame = 1000000000ull / uint64_t(mFps);
    while (mTaken > 0 && header.timeNs > mStartNs + mEmitted * nsPerFrame && !mFailed) emit();
    const bool resized = int(header.width) != mLast.width || int(header.height) != mLast.height;
    if (resized && !std::exchange(mResizeSaid, true)) {
        std::fprintf(stderr, "nprgl: video: the window is now %ux%u; its frames are cut or "
                     "padded to the video's %dx%d\n", header.width, header.height, mLast.width,
                     mLast.height);
    }
    // Bottom row first to top row first, cut or padded with black to the file's size.
    const size_t rowBytes = size_t(mLast.width) * 4;
    const size_t copyBytes = std::min<size_t>(header.width, size_t(mLast.width)) * 4;
    mLast.rgba.assign(rowBytes * size_t(mLast.height), 0);
    for (int y = 0; y < mLast.height && uint32_t(y) < header.height; ++y) {
        const uint8_t* from = mPixels.data() + size_t(header.height - 1 - y) * header.width * 4;
        std::memcpy(mLast.rgba.data() + size_t(y) * rowBytes, from, copyBytes);
    }
    mLast.makeOpaque();
    ++mTaken;
    mLastFrame = header.frame;
    mDropped = header.dropped - mDroppedBefore;
    mLastEmitted = false;
    if (mEmitted == 0) emit();
}

void VideoReceiver::emit()
{
    std::string error;
    if (!mWriter->add(mLast, error)) {
        std::fprintf(stderr, "nprgl: video %s: %s; the rest of this recording is not written\n",
                     fileName(mFiles).c_str(), error.c_str());
        mFailed = true;
        return;
    }
    ++mEmitted;
    mLastEmitted = true;
}

std::string VideoReceiver::fileName(uint32_t index) const
{
    if (index <= 1) return mPath;
    const std::filesystem::path path(mPath);
    const std::string name =
        path.stem().string() + "-" + std::to_string(index) + path.extension().string();
    return (path.parent_path() / name).string();
}

void VideoReceiver::startFile()
{
    ++mFiles;
    mWriter = std::make_unique<VideoWriter>();
    mEmitted = mTaken = mDropped = 0;
    mLastEmitted = mFailed = false;
    std::string error;
    if (!mWriter->open(fileName(mFiles), mFps, error, VideoWriter::Speed::Live)) {
        std::fprintf(stderr, "nprgl: video: %s\n", error.c_str());
        mFailed = true;
    }
}

void VideoReceiver::endFile()
{
    if (!mWriter) return;
    if (!mFailed && mTaken > 0 && !mLastEmitted) emit();
    std::string error;
    const bool finished = mWriter->finish(error);
    const std::string name = fileName(mFiles);
    if (!finished) {
        std::fprintf(stderr, "nprgl: video %s: %s\n", name.c_str(), error.c_str());
    } else if (mEmitted > 0) {
        const std::string dropped =
            mDropped ? "; " + std::to_string(mDropped) +
                           " not taken while the one before was still on its way"
                     : "";
        std::fprintf(stderr,
                     "nprgl: video %s: %.1f s at %d fps (%llu frame%s) from %llu frame%s of "
                     "process %u (frames %llu to %llu)%s\n",
                     name.c_str(), seconds(mEmitted, mFps), mFps,
                     static_cast<unsigned long long>(mEmitted), mEmitted == 1 ? "" : "s",
                     static_cast<unsigned long long>(mTaken), mTaken == 1 ? "" : "s", mPid,
                     static_cast<unsigned long long>(mFirstFrame),
                     static_cast<unsigned long long>(mLastFrame), dropped.c_str());
    }
    mWriter.reset();
}

void VideoReceiver::finish()
{
    // The program's last frames are on their way until its processes close the connection;
    // a process of it still running (a daemon it started) is not waited for.
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
    for (int idle = 0; mActive && idle < 20 && std::chrono::steady_clock::now() < deadline;) {
        if (readable(mActive->fd, 100)) {
            if (!readFrame()) mActive.reset();
            idle = 0;
        } else {
            ++idle;
        }
    }
    mActive.reset();
    endFile();
    if (mFiles == 0) {
        std::fprintf(stderr, "nprgl: video: no frame was recorded (the program drew none, or "
                     "the video key never started a recording); no %s\n", mPath.c_str());
    }
}

} // namespace nprgl::cli
