#pragma once

#include "capture/Metadata.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

typedef struct ZSTD_CCtx_s ZSTD_CCtx;

namespace nprgl::capture {

// Writes a capture file (docs/capture-format.md). Every frame reaches the file with write(2)
// before writeFrame returns, so a file whose program was killed still reads back. Calls are
// serialised by an internal mutex, so several recording threads may share one writer.
// Never throws; failures return false (or, for putBlob, leave hasBlob false) and lastError()
// says why. After an I/O error the writer refuses everything until it is reopened, so the
// file keeps ending at its last whole frame.
class CaptureWriter {
public:
    CaptureWriter();
    ~CaptureWriter();
    CaptureWriter(const CaptureWriter&) = delete;
    CaptureWriter& operator=(const CaptureWriter&) = delete;

    // What is at a path a capture is to be written to.
    enum class Target {
        Free,    // nothing, or an empty regular file
        Capture, // a regular file that starts as an nprgl capture
        Other,   // a regular file of anything else, never overwritten
        Refused, // a FIFO, device, directory, or a path that cannot be checked
    };
    // Looks at path without opening anything but a regular file (never blocks); why says
    // what it is when not Free or Capture.
    static Target checkTarget(const std::string& path, std::string& why);

    // Creates path, or replaces the capture there when replaceCapture, and writes the header
    // (magic, format version, metadata). Anything else at path is refused and left as it is:
    // a file that is not a capture, a capture unless replaceCapture, a FIFO, a device...
    bool open(const std::string& path, const Metadata& meta, std::string& error,
              bool replaceCapture = true);
    // Writes the header again with meta, which must encode to as many bytes as open()'s (the
    // same fields, another drawable size): a program resizes its window after making its
    // context current, before its first frame is shown.
    bool rewriteMetadata(const Metadata& meta);
    // Stores a blob once per file: returns its hash; a blob already stored writes nothing.
    // Blobs are written (compressed) before the next frame chunk that may reference them.
    BlobHash putBlob(const void* data, size_t size);
    bool hasBlob(BlobHash hash) const;
    // Appends one complete frame of stream contextId (1, 2, ...), zstd-compressed. When it
    // returns true, the frame and the blobs before it are on disk (write(2), no buffering).
    bool writeFrame(uint32_t contextId, uint64_t frameNumber, const void* calls, size_t size);
    // Cumulative counts of calls the recorder did not capture, by name; the reader keeps the
    // last chunk written.
    bool writeCallCounts(const std::vector<std::pair<std::string, uint64_t>>& counts);
    // Writes pending blobs, the index and the footer, and closes the file. Optional: a file
    // without it is still readable by scanning. In a forked child it writes nothing, closes
    // the inherited descriptor and returns false.
    bool close(std::string& error);
    // True if this process is not the one that opened the file (after fork(): the child must
    // open its own file, never append to the parent's).
    bool ownedByOtherProcess() const;

    // True while a file is open, also in a forked child that inherited the parent's (check
    // ownedByOtherProcess). Takes no lock, so it is safe in such a child.
    bool isOpen() const;
    // zstd level for frames and blobs; the default (1) favours recording speed.
    void setCompressionLevel(int level);
    std::string lastError() const;
    // Bytes written so far (header, chunks), not counting blobs still pending.
    uint64_t bytesWritten() const;

private:
    struct FrameEntry {
        uint64_t offset;
        uint32_t contextId;
        uint64_t frameNumber;
        uint64_t storedSize;
        uint64_t rawSize;
    };
    struct BlobEntry {
        BlobHash hash;
        uint64_t offset;
        uint64_t storedSize;
        uint64_t rawSize;
    };

    // Appends data to mPending, zstd-compressed when that makes it smaller. Returns the stored
    // size; codec says how it was stored.
    uint64_t appendBody(const void* data, size_t size, uint32_t& codec);
    // Writes mPending at the end of the file; on failure cuts the file back and stops.
    bool flushPending();
    bool usable(const char* what);
    void setError(std::string message);
    // Magic, format version and the META chunk; a reason when meta cannot be recorded.
    static std::string encodeHeader(const Metadata& meta, std::vector<uint8_t>& head);
    void resetLocked();
    void dropInheritedFile();

    mutable std::mutex mMutex;
    std::atomic<int> mFd{-1}; // read without the lock by isOpen
    std::atomic<int> mOwnerPid{0}; // read without the lock: a forked child may not take it
    bool mFailed = false;
    int mLevel = 1;
    std::string mPath;
    std::string mError;
    uint64_t mOffset = 0; // end of what is safely in the file
    size_t mHeaderSize = 0;
    ZSTD_CCtx* mCctx = nullptr;
    std::vector<uint8_t> mPending; // chunks not yet written, starting at mOffset
    std::vector<BlobEntry> mPendingBlobs;
    std::vector<FrameEntry> mFrames;
    std::vector<BlobEntry> mBlobs;
    std::unordered_set<BlobHash> mKnownBlobs;
    uint64_t mCountsOffset = 0;
};

} // namespace nprgl::capture
