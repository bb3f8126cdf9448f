#include "frame/LiveVideo.h"

#include "common/Log.h"
#include "common/SocketIo.h"
#include "frame/FrameGrabber.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <pthread.h>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>
#include <utility>

namespace nprgl {

namespace {

std::mutex gInstanceMutex;
LiveVideo* gInstance = nullptr; // never destroyed: its thread may outlive static destructors
pid_t gInstancePid = 0;

std::string environment(const char* name)
{
    const char* value = std::getenv(name);
    return value ? value : "";
}

uint64_t monotonicNs()
{
    timespec now {};
    clock_gettime(CLOCK_MONOTONIC, &now);
    return uint64_t(now.tv_sec) * 1000000000u + uint64_t(now.tv_nsec);
}

} // namespace

LiveVideo* LiveVideo::instance()
{
    static const std::string name = environment(video::kSocketVariable);
    if (name.empty()) return nullptr;
    std::lock_guard lock(gInstanceMutex);
    if (!gInstance || gInstancePid != getpid()) {
        static bool registered = false;
        const int fps = std::atoi(environment(video::kFpsVariable).c_str());
        gInstance = new LiveVideo(name, environment(video::kStartVariable) == "key", fps);
        gInstancePid = getpid();
        if (!registered) {
            registered = true;
            std::atexit([] {
                std::lock_guard guard(gInstanceMutex);
                if (gInstance && gInstancePid == getpid()) gInstance->flushAtExit();
            });
        }
    }
    return gInstance;
}

LiveVideo::LiveVideo(std::string socketName, bool waitForKey, int fps)
    : mSocketName(std::move(socketName)), mRecording(!waitForKey), mSpan(waitForKey ? 0 : 1),
      mPeriodNs(fps >= 1 && fps <= 1000 ? 1000000000ull / uint64_t(fps) : 0)
{
}

bool LiveVideo::wants(uint32_t serial)
{
    std::lock_guard lock(mMutex);
    if (!mRecording || mStopped) return false;
    if (mContext == 0) mContext = serial;
    if (mContext != serial) {
        if (!mOtherSaid) {
            NPRGL_INFO("video: context %u is the one recorded; context %u is not", mContext,
                       serial);
            mOtherSaid = true;
        }
        return false;
    }
    const uint64_t now = monotonicNs();
    const uint64_t start = mSpanStartNs ? mSpanStartNs : now;
    const uint64_t slot = mPeriodNs ? (now - start) / mPeriodNs : 0;
    // Still in the video frame of the last frame read: the video would not show it.
    if (mSpanStartNs != 0 && mPeriodNs != 0 && slot <= mLastSlot) return false;
    if (mQueuedFull) {
        ++mDropped;
        return false;
    }
    mSpanStartNs = start;
    mLastSlot = slot;
    mWantedNs = now;
    return true;
}

void LiveVideo::addFrame(uint32_t serial, uint64_t frame, const ContextCaps& caps, int width,
                         int height)
{
    const char* why = FrameGrabber::cannotRead(caps, width, height);
    if (!why && (width > int(video::kMaxSide) || height > int(video::kMaxSide))) {
        why = "larger than a video frame may be";
    }
    if (why) {
        std::lock_guard lock(mMutex);
        ++mDropped;
        if (!std::exchange(mUnreadableSaid, true)) {
            NPRGL_WARN("video: context %u: frame %llu cannot be read (%s); not in the video "
                       "(said once)", serial, static_cast<unsigned long long>(frame), why);
        }
        return;
    }
    // wants() said the queue is empty: the sending thread does not touch mQueued until it is
    // marked full below. Its storage is kept, so a frame of an unchanged size allocates nothing.
    mQueued.resize(size_t(width) * size_t(height) * 4);
    const GLenum refused = FrameGrabber::readFrame(caps, width, height, mQueued.data());
    std::lock_guard lock(mMutex);
    if (refused != GL_NO_ERROR) {
        ++mDropped;
        if (!std::exchange(mUnreadableSaid, true)) {
            NPRGL_WARN("video: the driver refused to read frame %llu (GL error 0x%x); not in "
                       "the video (said once)", static_cast<unsigned long long>(frame), refused);
        }
        return;
    }
    mQueuedHeader = video::FrameHeader{};
    mQueuedHeader.span = mSpan;
    mQueuedHeader.width = uint32_t(width);
    mQueuedHeader.height = uint32_t(height);
    mQueuedHeader.timeNs = mWantedNs;
    mQueuedHeader.frame = frame;
    mQueuedHeader.dropped = mDropped;
    mQueuedFull = true;
    if (!mThreadStarted) {
        mThreadStarted = true;
        // The program's signals are handled on its own threads, never on this one.
        sigset_t all, old;
        sigfillset(&all);
        pthread_sigmask(SIG_SETMASK, &all, &old);
        std::thread(&LiveVideo::sendLoop, this).detach();
        pthread_sigmask(SIG_SETMASK, &old, nullptr);
    }
    mChanged.notify_all();
}

void LiveVideo::toggle(uint32_t serial)
{
    std::lock_guard lock(mMutex);
    if (mStopped) {
        NPRGL_WARN("video key: no video is being written (the connection to nprgl ended)");
        return;
    }
    mRecording = !mRecording;
    if (mRecording) {
        ++mSpan;
        mSpanStartNs = 0;
        NPRGL_INFO("video key (context %u): recording %u started", serial, mSpan);
    } else {
        NPRGL_INFO("video key (context %u): recording %u stopped", serial, mSpan);
    }
}

bool LiveVideo::connectToReceiver()
{
    mSocket = SocketIo::connectAbstract(mSocketName);
    if (mSocket < 0 && errno == ENAMETOOLONG) {
        NPRGL_ERROR("video: %s is too long a socket name; no video", video::kSocketVariable);
        return false;
    }
    if (mSocket < 0) {
        NPRGL_ERROR("video: cannot reach the nprgl command that asked for it (%s); no video",
                    std::strerror(errno));
        return false;
    }
    video::Hello hello;
    hello.pid = uint32_t(getpid());
    char answer = 0;
    if (!SocketIo::sendAll(mSocket, &hello, sizeof hello) ||
        !SocketIo::readAll(mSocket, &answer, 1)) {
        NPRGL_ERROR("video: the nprgl command did not answer; no video");
        return false;
    }
    if (answer != video::kAccepted) {
        NPRGL_INFO("video: another process of this run is being recorded; process %d is not",
                   int(getpid()));
        return false;
    }
    return true;
}

void LiveVideo::sendLoop()
{
    const bool connected = connectToReceiver();
    for (bool ok = connected; ok;) {
        video::FrameHeader header;
        {
            std::unique_lock lock(mMutex);
            mChanged.wait(lock, [&] { return mQueuedFull; });
            std::swap(mQueued, mSending);
            header = mQueuedHeader;
            mQueuedFull = false;
            mSendingBusy = true;
        }
        ok = SocketIo::sendAll(mSocket, &header, sizeof header) &&
             SocketIo::sendAll(mSocket, mSending.data(), mSending.size());
        std::lock_guard lock(mMutex);
        mSendingBusy = false;
        if (!ok) {
            NPRGL_WARN("video: the nprgl command stopped reading (%s); frames from %llu on are "
                       "not in the video", std::strerror(errno),
                       static_cast<unsigned long long>(header.frame));
        }
        mChanged.notify_all();
    }
    std::lock_guard lock(mMutex);
    mStopped = true;
    mQueuedFull = false;
    if (mSocket >= 0) close(mSocket);
    mSocket = -1;
    mChanged.notify_all();
}

void LiveVideo::flushAtExit()
{
    std::unique_lock lock(mMutex);
    if (!mThreadStarted) return;
    // Bounded: a receiver that stopped reading must not keep the program from ending.
    mChanged.wait_for(lock, std::chrono::seconds(3),
                      [&] { return mStopped || (!mQueuedFull && !mSendingBusy); });
}

} // namespace nprgl
