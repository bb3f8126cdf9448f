#include "frame/CaptureSession.h"

#include "common/Log.h"
#include "common/ProcessName.h"
#include "frame/Recorder.h"
#include "shim/Context.h"
#include "shim/RealGl.h"
#include "stream/Opcodes.h"

#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <unistd.h>

namespace nprgl {

namespace {

// The process `nprgl record` started (it execs the program, so the pid is the same) writes
// the file it was asked for; any other process (a forked or spawned child) its own
// <name>.<pid>.nprgl. Without the command, the process that loaded the library first is it:
// claimOwnership() exports its pid, so that an exec'd child, which inherits NPRGL_RECORD,
// knows the name is not its own.
bool isMainRecordingProcess()
{
    const char* env = std::getenv("NPRGL_RECORD_PID");
    return env && *env && getpid() == pid_t(std::atol(env));
}

// Runs in the library's constructor, before the program can fork, exec or start threads.
// The path is made absolute so a child that changed its directory still writes beside it.
std::string claimOwnership(const char* path)
{
    std::error_code ec;
    std::string absolute = std::filesystem::absolute(path, ec).string();
    if (ec) absolute = path;
    const char* owner = std::getenv("NPRGL_RECORD_PID");
    if (!owner || !*owner) {
        setenv("NPRGL_RECORD", absolute.c_str(), 1);
        setenv("NPRGL_RECORD_PID", std::to_string(getpid()).c_str(), 1);
    }
    return absolute;
}

std::string pathForThisProcess(const std::string& base)
{
    if (isMainRecordingProcess()) return base;
    std::string stem = base;
    if (stem.size() > 6 && stem.compare(stem.size() - 6, 6, ".nprgl") == 0) {
        stem.resize(stem.size() - 6);
    }
    return stem + "." + std::to_string(getpid()) + ".nprgl";
}

// The first name <stem>.N.nprgl with nothing there, for a recording whose name holds a capture
// already (as apitrace does); empty when a thousand are taken.
std::string freeName(const std::string& path)
{
    std::string stem = path;
    if (stem.size() > 6 && stem.compare(stem.size() - 6, 6, ".nprgl") == 0) {
        stem.resize(stem.size() - 6);
    }
    for (int n = 1; n < 1000; ++n) {
        const std::string candidate = stem + "." + std::to_string(n) + ".nprgl";
        std::string why;
        using Target = capture::CaptureWriter::Target;
        if (capture::CaptureWriter::checkTarget(candidate, why) == Target::Free) return candidate;
    }
    return {};
}

void finishAtExit()
{
    if (CaptureSession* session = CaptureSession::instance()) session->finish();
}

} // namespace

CaptureSession* CaptureSession::instance()
{
    static CaptureSession* session = []() -> CaptureSession* {
        const char* path = std::getenv("NPRGL_RECORD");
        if (!path || !*path) return nullptr;
        FrameSet frames;
        std::string error;
        const char* range = std::getenv("NPRGL_RECORD_FRAMES");
        if (range && *range && !FrameSet::parse(range, frames, error)) {
            NPRGL_ERROR("NPRGL_RECORD_FRAMES: %s; recording every frame", error.c_str());
            frames = FrameSet();
        }
        // Lives until exit, after atexit runs.
        auto* s = new CaptureSession(claimOwnership(path), frames);
        std::atexit(finishAtExit);
        return s;
    }();
    return session;
}

CaptureSession::CaptureSession(std::string path, FrameSet frames)
    : mBasePath(std::move(path)), mFrames(std::move(frames)),
      mLastFrame(mFrames.empty() ? UINT64_MAX : mFrames.last())
{
}

bool CaptureSession::ensureOpenLocked(const Context& ctx)
{
    if (mFinished && !mWriter.ownedByOtherProcess()) return false; // never reopen (truncate)
    if (mWriter.isOpen() && !mWriter.ownedByOtherProcess()) return true;
    if (mWriter.isOpen()) {
        // A forked child: leave the parent's file alone and start one of our own.
        std::string ignored;
        mWriter.close(ignored);
        mOpenFailed = false;
        mFramesWritten = 0;
        mUncaptured.clear();
        mFinished = false;
        mPath = pathForThisProcess(mBasePath);
    } else if (mPath.empty()) {
        mPath = pathForThisProcess(mBasePath);
    }
    if (mOpenFailed) return false;
    capture::Metadata meta;
    meta.program = processName();
    meta.commandLine = processCommandLine();
    meta.glVendor = ctx.vendor();
    meta.glRenderer = ctx.renderer();
    meta.glVersion = ctx.version();
    meta.width = ctx.drawableWidth();
    meta.height = ctx.drawableHeight();
    if (meta.width <= 0 || meta.height <= 0) {
        // No drawable to ask (an EGL surfaceless context renders into its own framebuffers):
        // the viewport the program set is the size it draws at. Called from a GL call of
        // the recording thread, so its context is current.
        GLint viewport[4] = {0, 0, 0, 0};
        gRealGl.glGetIntegerv(GL_VIEWPORT, viewport);
        meta.width = viewport[2];
        meta.height = viewport[3];
    }
    meta.pid = uint32_t(getpid());
    // The names behind the opcodes a Stream can hold: up to the last recorded command.
    uint16_t recorded = 0;
    for (uint16_t i = 0; i < op::kCount; ++i)
        if (kOpcodeRecorded[i]) recorded = uint16_t(i + 1);
    meta.opcodeNames.assign(kOpcodeNames, kOpcodeNames + recorded);
    meta.startTimeUnix = uint64_t(std::time(nullptr));
    if (!mFrames.empty())
        meta.extra.emplace_back("recorded_frames", std::getenv("NPRGL_RECORD_FRAMES"));
    // Never overwrite what is not ours: a file of anything else, or a special file, is left
    // alone and the program runs unrecorded; a capture is replaced only when asked
    // (NPRGL_RECORD_FORCE=1, what `nprgl record --force` sets), else the recording takes a
    // new name beside it.
    const char* forceEnv = std::getenv("NPRGL_RECORD_FORCE");
    const bool force = forceEnv && std::string(forceEnv) == "1";
    std::string why;
    const auto target = capture::CaptureWriter::checkTarget(mPath, why);
    if (target == capture::CaptureWriter::Target::Other ||
        target == capture::CaptureWriter::Target::Refused) {
        NPRGL_ERROR("not recording: %s %s", mPath.c_str(), why.c_str());
        mOpenFailed = true;
        return false;
    }
    if (target == capture::CaptureWriter::Target::Capture && !force) {
        const std::string other = freeName(mPath);
        if (other.empty()) {
            NPRGL_ERROR("not recording: %s is a capture already, and no free name is left "
                        "beside it", mPath.c_str());
            mOpenFailed = true;
            return false;
        }
        NPRGL_WARN("%s is a capture already: recording to %s instead (NPRGL_RECORD_FORCE=1 or "
                   "nprgl record --force replaces it)",
                   mPath.c_str(), other.c_str());
        mPath = other;
    }
    std::string error;
    if (!mWriter.open(mPath, meta, error, force)) {
        NPRGL_ERROR("cannot record: %s", error.c_str());
        mOpenFailed = true;
        return false;
    }
    NPRGL_INFO("recording to %s", mPath.c_str());
    mMeta = std::move(meta);
    return true;
}

uint64_t CaptureSession::putBlob(const Context& ctx, const void* data, size_t size)
{
    {
        std::lock_guard lock(mMutex);
        if (!ensureOpenLocked(ctx)) return capture::hashBlob(data, size);
    }
    return mWriter.putBlob(data, size);
}

bool CaptureSession::writeFrame(const Context& ctx, uint64_t frame, const uint8_t* calls,
                                size_t size)
{
    std::lock_guard lock(mMutex);
    if (frame > mLastFrame || !ensureOpenLocked(ctx)) return false;
    // The header opened with the size at the first blob or frame, which may come before the
    // program sized its window (glretrace, SDL); the first frame shown says.
    if (mFramesWritten == 0 && ctx.drawableWidth() > 0 && ctx.drawableHeight() > 0 &&
        (ctx.drawableWidth() != mMeta.width || ctx.drawableHeight() != mMeta.height)) {
        capture::Metadata sized = mMeta;
        sized.width = ctx.drawableWidth();
        sized.height = ctx.drawableHeight();
        if (mWriter.rewriteMetadata(sized)) {
            mMeta = std::move(sized);
        } else {
            NPRGL_WARN("%s; it says %dx%d, the first frame was shown at %dx%d",
                       mWriter.lastError().c_str(), mMeta.width, mMeta.height, sized.width,
                       sized.height);
        }
    }
    // Later resizes do not change the file's size: said once each, per context.
    const std::pair shown{ctx.drawableWidth(), ctx.drawableHeight()};
    auto [seen, first] = mShownSizes.try_emplace(ctx.serial(), shown);
    if (!first && seen->second != shown) {
        seen->second = shown;
        NPRGL_WARN("context %u: the window is %dx%d from frame %llu on; the capture replays "
                   "every frame at its first frame's %dx%d (nprgl replay --size WxH to choose)",
                   ctx.serial(), shown.first, shown.second,
                   static_cast<unsigned long long>(frame), mMeta.width, mMeta.height);
    }
    if (!mWriter.writeFrame(ctx.serial(), frame, calls, size)) {
        NPRGL_ERROR("recording stopped at frame %llu: %s",
                    static_cast<unsigned long long>(frame), mWriter.lastError().c_str());
        mOpenFailed = true;
        return false;
    }
    ++mFramesWritten;
    if (mUncapturedChanged) {
        mWriter.writeCallCounts(mUncaptured);
        mUncapturedChanged = false;
    }
    if (frame == mLastFrame) finishLocked(); // complete with its index, whatever comes next
    return true;
}

void CaptureSession::attach(Recorder* recorder)
{
    std::lock_guard lock(mMutex);
    mRecorders.push_back(recorder);
}

void CaptureSession::detach(Recorder* recorder)
{
    std::lock_guard lock(mMutex);
    std::erase(mRecorders, recorder);
}

void CaptureSession::addUncaptured(const char* name, uint64_t count)
{
    std::lock_guard lock(mMutex);
    addUncapturedLocked(name, count);
}

void CaptureSession::addUncapturedLocked(const char* name, uint64_t count)
{
    for (auto& [n, c] : mUncaptured) {
        if (n == name) {
            c += count;
            mUncapturedChanged = true;
            return;
        }
    }
    mUncaptured.emplace_back(name, count);
    mUncapturedChanged = true;
}

void CaptureSession::finish()
{
    std::lock_guard lock(mMutex);
    finishLocked();
}

void CaptureSession::finishLocked()
{
    if (mWriter.isOpen() && !mWriter.ownedByOtherProcess()) mFinished = true;
    if (!mWriter.isOpen() || mWriter.ownedByOtherProcess()) return;
    for (Recorder* recorder : mRecorders) {
        recorder->takeUncaptured([this](const char* name, uint64_t count) {
            addUncapturedLocked(name, count);
        });
    }
    if (mUncapturedChanged) mWriter.writeCallCounts(mUncaptured);
    std::string error;
    if (!mWriter.close(error)) NPRGL_ERROR("closing %s: %s", mPath.c_str(), error.c_str());
    std::string report;
    for (const auto& [name, count] : mUncaptured) {
        report += (report.empty() ? "" : ", ") + name + " x" + std::to_string(count);
    }
    // Under `nprgl record` the command reads the file back and says it, however the program
    // ended; a child's own file is said here.
    const char* summary = std::getenv("NPRGL_RECORD_SUMMARY");
    const bool commandSaysIt = summary && std::strcmp(summary, "command") == 0 &&
                               isMainRecordingProcess();
    NPRGL_LOG(commandSaysIt ? LogLevel::Debug : LogLevel::Info,
              "recorded %llu frames to %s; not captured: %s",
              static_cast<unsigned long long>(mFramesWritten), mPath.c_str(),
              report.empty() ? "nothing" : report.c_str());
}

} // namespace nprgl
