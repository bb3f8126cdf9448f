#include "capture/CaptureWriter.h"

#include "capture/ByteWriter.h"
#include "capture/Format.h"

#include <zstd.h>

#include <cerrno>
#include <cstring>
#include <exception>
#include <new>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

namespace nprgl::capture {

namespace {

// Pending blobs are written early once they add up to this much, to bound memory.
constexpr size_t kPendingFlushBytes = size_t(8) << 20;
// A buffer that grew for one huge frame is given back rather than kept for the whole run.
constexpr size_t kPendingKeepCapacity = size_t(64) << 20;

// Returns 0 or the errno of the failure.
int writeAll(int fd, const uint8_t* data, size_t size)
{
    while (size > 0) {
        ssize_t n = ::write(fd, data, size);
        if (n < 0) {
            if (errno == EINTR) continue;
            return errno;
        }
        if (n == 0) return ENOSPC;
        data += n;
        size -= size_t(n);
    }
    return 0;
}

void store32(uint8_t* p, uint32_t v)
{
    for (int i = 0; i < 4; ++i) p[i] = uint8_t(v >> (8 * i));
}

// Empty when everything fits the limits a reader enforces.
std::string checkString(const std::string& s, const char* what)
{
    if (s.size() <= kMaxStringSize) return {};
    return std::string(what) + " is " + std::to_string(s.size()) + " bytes, over the limit of " +
           std::to_string(kMaxStringSize);
}

std::string checkMetadata(const Metadata& meta)
{
    std::string why = checkString(meta.program, "program name");
    for (const std::string& arg : meta.commandLine)
        if (why.empty()) why = checkString(arg, "a command line argument");
    if (why.empty()) why = checkString(meta.glVendor, "GL vendor");
    if (why.empty()) why = checkString(meta.glRenderer, "GL renderer");
    if (why.empty()) why = checkString(meta.glVersion, "GL version");
    for (const auto& [key, value] : meta.extra) {
        if (why.empty()) why = checkString(key, "an extra key");
        if (why.empty()) why = checkString(value, "an extra value");
    }
    for (const std::string& name : meta.opcodeNames)
        if (why.empty()) why = checkString(name, "an opcode name");
    return why;
}

} // namespace

CaptureWriter::CaptureWriter() = default;

CaptureWriter::~CaptureWriter()
{
    if (ownedByOtherProcess()) {
        dropInheritedFile();
    } else if (mFd >= 0) {
        std::string ignored;
        close(ignored);
    }
    ZSTD_freeCCtx(mCctx);
}

bool CaptureWriter::open(const std::string& path, const Metadata& meta, std::string& error,
                         bool replaceCapture)
{
    if (ownedByOtherProcess()) dropInheritedFile();
    std::lock_guard lock(mMutex);
    if (mFd >= 0) {
        error = path + ": cannot open: this writer still has " + mPath + " open";
        return false;
    }
    try {
        resetLocked();
        std::vector<uint8_t> head;
        if (std::string why = encodeHeader(meta, head); !why.empty()) {
            error = path + ": cannot record: " + why;
            return false;
        }
        if (!mCctx) mCctx = ZSTD_createCCtx();
        if (!mCctx) {
            error = path + ": cannot create a zstd context";
            return false;
        }

        // Not truncated on open: what is there is looked at first. Looked at before it is
        // opened too, as opening a FIFO for writing waits for a reader.
        std::string why;
        const Target target = checkTarget(path, why);
        if (target == Target::Other || target == Target::Refused ||
            (target == Target::Capture && !replaceCapture)) {
            error = path + ": " + (target == Target::Capture ? "an nprgl capture is there; " +
                                                                  std::string("not replaced")
                                                             : why);
            return false;
        }
        int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NONBLOCK | O_NOCTTY, 0644);
        if (fd < 0) {
            error = path + ": cannot create: " + std::strerror(errno);
            return false;
        }
        // The same checks on what was opened, in case the path changed in between.
        struct stat st;
        uint8_t magic[sizeof kMagic] = {};
        const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
        const bool empty = regular && st.st_size == 0;
        const bool capture = regular &&
                             ::pread(fd, magic, sizeof magic, 0) == ssize_t(sizeof magic) &&
                             std::memcmp(magic, kMagic, sizeof kMagic) == 0;
        if (!empty && !(capture && replaceCapture)) {
            error = path + ": changed while it was being opened; left as it is";
            ::close(fd);
            return false;
        }
        if (!empty && ::ftruncate(fd, 0) != 0) {
            error = path + ": cannot truncate: " + std::strerror(errno);
            ::close(fd);
            return false;
        }
        if (int err = writeAll(fd, head.data(), head.size())) {
            error = path + ": cannot write the header: " + std::strerror(err);
            ::close(fd);
            return false;
        }
        mFd = fd;
        mPath = path;
        mOffset = head.size();
        mHeaderSize = head.size();
        mOwnerPid = int(::getpid());
        return true;
    } catch (const std::exception& e) {
        error = path + ": cannot open: " + e.what();
        return false;
    }
}

CaptureWriter::Target CaptureWriter::checkTarget(const std::string& path, std::string& why)
{
    why.clear();
    struct stat st;
    if (::stat(path.c_str(), &st) != 0) {
        if (errno == ENOENT) return Target::Free;
        why = std::string("cannot look at it: ") + std::strerror(errno);
        return Target::Refused;
    }
    if (!S_ISREG(st.st_mode)) {
        why = specialFileKind(st.st_mode) + "; a capture is written only to a regular file";
        return Target::Refused;
    }
    if (st.st_size == 0) return Target::Free;
    int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
    if (fd < 0) {
        why = std::string("cannot read it to see whether it is a capture: ") +
              std::strerror(errno) + "; left as it is";
        return Target::Refused;
    }
    uint8_t magic[sizeof kMagic] = {};
    const bool capture = ::pread(fd, magic, sizeof magic, 0) == ssize_t(sizeof magic) &&
                         std::memcmp(magic, kMagic, sizeof kMagic) == 0;
    ::close(fd);
    if (capture) return Target::Capture;
    why = "exists and is not an nprgl capture; it is never overwritten";
    return Target::Other;
}

std::string CaptureWriter::encodeHeader(const Metadata& meta, std::vector<uint8_t>& head)
{
    std::string why = checkMetadata(meta);
    head.assign(kMagic, kMagic + sizeof kMagic);
    ByteWriter w(head);
    w.u32(kFormatVersion);
    w.u32(0);
    size_t start = beginChunk(head, kChunkMeta);
    if (why.empty()) encodeMetadata(meta, head);
    if (why.empty() && head.size() - start - kChunkHeaderSize > kMaxSmallChunk)
        why = "the metadata is over the limit of " + std::to_string(kMaxSmallChunk) + " bytes";
    if (why.empty()) finishChunk(head, start);
    return why;
}

bool CaptureWriter::rewriteMetadata(const Metadata& meta)
{
    std::lock_guard lock(mMutex);
    if (!usable("rewrite the header")) return false;
    try {
        std::vector<uint8_t> head;
        if (std::string why = encodeHeader(meta, head); !why.empty()) {
            setError(mPath + ": header not rewritten: " + why);
            return false;
        }
        if (head.size() != mHeaderSize) {
            setError(mPath + ": header not rewritten: its size would change");
            return false;
        }
        // At its place: the descriptor's own offset (the file's end) is left as it is.
        for (size_t done = 0; done < head.size();) {
            const ssize_t n = ::pwrite(mFd, head.data() + done, head.size() - done, off_t(done));
            if (n < 0 && errno == EINTR) continue;
            if (n <= 0) {
                setError(mPath + ": cannot rewrite the header: " + std::strerror(errno));
                return false;
            }
            done += size_t(n);
        }
        return true;
    } catch (const std::exception& e) {
        setError(mPath + ": header not rewritten: " + e.what());
        return false;
    }
}

BlobHash CaptureWriter::putBlob(const void* data, size_t size)
{
    if (!data && size > 0) {
        std::lock_guard lock(mMutex);
        setError("blob not stored: null data of " + std::to_string(size) + " bytes");
        return 0;
    }
    BlobHash hash = hashBlob(data, size);
    std::lock_guard lock(mMutex);
    if (mKnownBlobs.count(hash) || !usable("store a blob")) return hash;
    if (size > kMaxRawSize) {
        setError(mPath + ": blob of " + std::to_string(size) + " bytes not stored (limit " +
                 std::to_string(kMaxRawSize) + ")");
        return hash;
    }
    size_t before = mPending.size();
    size_t blobsBefore = mPendingBlobs.size();
    try {
        size_t start = beginChunk(mPending, kChunkBlob);
        ByteWriter w(mPending);
        w.u64(hash);
        w.u64(size);
        size_t codecAt = mPending.size();
        w.u32(0);
        w.u32(0);
        uint32_t codec = kCodecStored;
        uint64_t stored = appendBody(data, size, codec);
        store32(mPending.data() + codecAt, codec);
        finishChunk(mPending, start);
        mPendingBlobs.push_back(BlobEntry{hash, mOffset + start, stored, size});
        mKnownBlobs.insert(hash);
    } catch (const std::exception& e) {
        mPending.resize(before);
        mPendingBlobs.resize(blobsBefore);
        setError(mPath + ": blob not stored: " + e.what());
        return hash;
    }
    if (mPending.size() >= kPendingFlushBytes) flushPending();
    return hash;
}

bool CaptureWriter::hasBlob(BlobHash hash) const
{
    std::lock_guard lock(mMutex);
    return mKnownBlobs.count(hash) != 0;
}

bool CaptureWriter::writeFrame(uint32_t contextId, uint64_t frameNumber, const void* calls,
                               size_t size)
{
    std::lock_guard lock(mMutex);
    if (!usable("write a frame")) return false;
    if (size > kMaxRawSize || (size > 0 && !calls)) {
        setError(mPath + ": frame " + std::to_string(frameNumber) + " of " +
                 std::to_string(size) + " bytes not written (limit " +
                 std::to_string(kMaxRawSize) + ")");
        return false;
    }
    size_t before = mPending.size();
    try {
        size_t start = beginChunk(mPending, kChunkFrame);
        ByteWriter w(mPending);
        w.u32(contextId);
        size_t codecAt = mPending.size();
        w.u32(0);
        w.u64(frameNumber);
        w.u64(size);
        uint32_t codec = kCodecStored;
        uint64_t stored = appendBody(calls, size, codec);
        store32(mPending.data() + codecAt, codec);
        finishChunk(mPending, start);
        mFrames.reserve(mFrames.size() + 1); // nothing may fail once the frame is on disk
        FrameEntry entry{mOffset + start, contextId, frameNumber, stored, size};
        if (!flushPending()) return false;
        mFrames.push_back(entry);
        return true;
    } catch (const std::exception& e) {
        mPending.resize(before);
        setError(mPath + ": frame " + std::to_string(frameNumber) + " not written: " + e.what());
        return false;
    }
}

bool CaptureWriter::writeCallCounts(const std::vector<std::pair<std::string, uint64_t>>& counts)
{
    std::lock_guard lock(mMutex);
    if (!usable("write call counts")) return false;
    size_t before = mPending.size();
    try {
        for (const auto& entry : counts) {
            std::string why = checkString(entry.first, "a call name");
            if (!why.empty()) {
                setError(mPath + ": call counts not written: " + why);
                return false;
            }
        }
        size_t start = beginChunk(mPending, kChunkCounts);
        encodeCallCounts(counts, mPending);
        if (mPending.size() - start - kChunkHeaderSize > kMaxSmallChunk) {
            mPending.resize(before);
            setError(mPath + ": call counts not written: over the limit of " +
                     std::to_string(kMaxSmallChunk) + " bytes");
            return false;
        }
        finishChunk(mPending, start);
        uint64_t offset = mOffset + start;
        if (!flushPending()) return false;
        mCountsOffset = offset;
        return true;
    } catch (const std::exception& e) {
        mPending.resize(before);
        setError(mPath + ": call counts not written: " + e.what());
        return false;
    }
}

bool CaptureWriter::close(std::string& error)
{
    if (ownedByOtherProcess()) {
        error = mPath + ": not closed: the file belongs to process " +
                std::to_string(mOwnerPid.load()) + "; this forked child leaves it alone";
        dropInheritedFile();
        return false;
    }
    std::lock_guard lock(mMutex);
    if (mFd < 0) {
        error = "no capture file is open";
        return false;
    }
    bool ok = !mFailed;
    if (!ok) error = mError;
    if (ok) {
        try {
            size_t start = beginChunk(mPending, kChunkIndex);
            uint64_t indexOffset = mOffset + start;
            ByteWriter w(mPending);
            w.u64(mFrames.size());
            w.u64(mBlobs.size() + mPendingBlobs.size());
            w.u64(mCountsOffset);
            for (const FrameEntry& f : mFrames) {
                w.u64(f.offset);
                w.u32(f.contextId);
                w.u32(0);
                w.u64(f.frameNumber);
                w.u64(f.storedSize);
                w.u64(f.rawSize);
            }
            for (const auto* list : {&mBlobs, &mPendingBlobs}) {
                for (const BlobEntry& b : *list) {
                    w.u64(b.hash);
                    w.u64(b.offset);
                    w.u64(b.storedSize);
                    w.u64(b.rawSize);
                }
            }
            finishChunk(mPending, start);
            start = beginChunk(mPending, kChunkFooter);
            w.u64(indexOffset);
            finishChunk(mPending, start);
            ok = flushPending();
            if (!ok) error = mError;
        } catch (const std::exception& e) {
            ok = false;
            error = mPath + ": index not written: " + e.what();
        }
    }
    if (::close(mFd) != 0 && ok) {
        ok = false;
        error = mPath + ": close failed: " + std::strerror(errno);
    }
    mFd = -1;
    resetLocked();
    return ok;
}

bool CaptureWriter::ownedByOtherProcess() const
{
    int owner = mOwnerPid.load();
    return owner != 0 && owner != int(::getpid());
}

bool CaptureWriter::isOpen() const
{
    return mFd >= 0;
}

void CaptureWriter::setCompressionLevel(int level)
{
    std::lock_guard lock(mMutex);
    mLevel = level;
}

std::string CaptureWriter::lastError() const
{
    std::lock_guard lock(mMutex);
    return mError;
}

uint64_t CaptureWriter::bytesWritten() const
{
    std::lock_guard lock(mMutex);
    return mOffset;
}

uint64_t CaptureWriter::appendBody(const void* data, size_t size, uint32_t& codec)
{
    size_t at = mPending.size();
    size_t bound = ZSTD_compressBound(size);
    mPending.resize(at + bound);
    size_t n = ZSTD_compressCCtx(mCctx, mPending.data() + at, bound, data, size, mLevel);
    if (!ZSTD_isError(n) && n < size) {
        mPending.resize(at + n);
        codec = kCodecZstd;
        return n;
    }
    // Incompressible (or empty): storing it is smaller and faster to read.
    mPending.resize(at + size);
    if (size > 0) std::memcpy(mPending.data() + at, data, size);
    codec = kCodecStored;
    return size;
}

bool CaptureWriter::flushPending()
{
    if (mPending.empty()) return true;
    if (int err = writeAll(mFd, mPending.data(), mPending.size())) {
        // Cut off the partial chunk so that nothing written later can follow garbage.
        if (::ftruncate(mFd, off_t(mOffset)) == 0) ::lseek(mFd, off_t(mOffset), SEEK_SET);
        mFailed = true;
        mError = mPath + ": write failed at offset " + std::to_string(mOffset) + ": " +
                 std::strerror(err) + "; recording stopped";
        for (const BlobEntry& b : mPendingBlobs) mKnownBlobs.erase(b.hash);
        mPendingBlobs.clear();
        mPending.clear();
        return false;
    }
    mOffset += mPending.size();
    mBlobs.insert(mBlobs.end(), mPendingBlobs.begin(), mPendingBlobs.end());
    mPendingBlobs.clear();
    mPending.clear();
    if (mPending.capacity() > kPendingKeepCapacity) std::vector<uint8_t>().swap(mPending);
    return true;
}

bool CaptureWriter::usable(const char* what)
{
    if (mFd < 0) {
        mError = std::string("cannot ") + what + ": no capture file is open";
        return false;
    }
    if (ownedByOtherProcess()) {
        mError = mPath + ": cannot " + what + ": the file belongs to process " +
                 std::to_string(mOwnerPid.load()) + "; a forked child must open its own";
        return false;
    }
    return !mFailed;
}

void CaptureWriter::setError(std::string message)
{
    mError = std::move(message);
}

void CaptureWriter::resetLocked()
{
    mOwnerPid = 0;
    mFailed = false;
    mPath.clear();
    mError.clear();
    mOffset = 0;
    mPending.clear();
    mPendingBlobs.clear();
    mFrames.clear();
    mBlobs.clear();
    mKnownBlobs.clear();
    mCountsOffset = 0;
}

void CaptureWriter::dropInheritedFile()
{
    // Only the forking thread survives fork(); a lock another thread held at that moment is
    // never released, so the child builds a fresh mutex instead of taking the old one.
    new (&mMutex) std::mutex;
    if (mFd >= 0) ::close(mFd);
    mFd = -1;
    resetLocked();
}

} // namespace nprgl::capture
