#pragma once

#include "capture/Metadata.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace nprgl::capture {

// Reads a capture file (docs/capture-format.md). The file is untrusted: every length and
// offset is checked against the file size and the format's limits before anything is
// allocated, and every chunk's checksum before its content is believed. Errors are one line
// naming the file and the byte offset. Never throws. After open, the const members may be
// called from several threads at once (reads use pread).
class CaptureReader {
public:
    struct FrameInfo {
        uint32_t contextId;
        uint64_t frameNumber;
        uint64_t offset;         // of the frame's chunk in the file
        uint64_t compressedSize; // stored body size
        uint64_t rawSize;
    };
    struct BlobInfo {
        BlobHash hash;
        uint64_t offset; // of the blob's chunk in the file
        uint64_t compressedSize;
        uint64_t rawSize;
    };

    CaptureReader() = default;
    ~CaptureReader();
    CaptureReader(const CaptureReader&) = delete;
    CaptureReader& operator=(const CaptureReader&) = delete;

    // A stretch of the file that could not be read: a damaged chunk, bytes between chunks or
    // after the footer, or a damaged index. message is one line naming the file and offset.
    struct Damage {
        uint64_t offset;
        uint64_t size; // bytes skipped (0 for a damaged index, whose frames were scanned)
        std::string message;
    };
    struct FrameId {
        uint32_t contextId;
        uint64_t frameNumber;
        bool operator==(const FrameId&) const = default;
    };

    // Validates magic and version, reads metadata, loads the index from the footer, or, when
    // the footer is missing or damaged, scans chunk by chunk. A damaged chunk or stray bytes
    // are skipped to the next whole chunk (each stretch is listed in damage()); an incomplete
    // last chunk, which a recording stopped while writing leaves, ends the scan. Refuses a
    // path that is not a regular file at once (FIFOs, devices and directories are never read).
    bool open(const std::string& path, std::string& error);
    // The same on a copy of bytes already in memory; name stands for the path in messages.
    bool openMemory(const void* data, size_t size, const std::string& name, std::string& error);

    const Metadata& metadata() const { return mMeta; }
    const std::vector<FrameInfo>& frames() const { return mFrames; }
    // Decompresses frame index (in file order) alone, after checking its chunk's checksum.
    bool readFrame(size_t index, std::vector<uint8_t>& calls, std::string& error) const;
    // Checks the chunk's checksum and that the content hashes to hash.
    bool readBlob(BlobHash hash, std::vector<uint8_t>& out, std::string& error) const;
    bool hasBlob(BlobHash hash) const { return mBlobIndex.count(hash) != 0; }
    const std::vector<BlobInfo>& blobs() const { return mBlobs; }
    size_t blobCount() const { return mBlobs.size(); }
    uint64_t blobBytes() const { return mBlobBytes; } // uncompressed total
    uint64_t fileBytes() const { return mFileSize; }
    const std::vector<std::pair<std::string, uint64_t>>& callCounts() const
    {
        return mCallCounts;
    }
    // True when the index was missing (or damaged) and the file was scanned.
    bool recovered() const { return mRecovered; }
    // True when the file has its footer: its recording closed it.
    bool closed() const { return mClosed; }
    // What was found damaged at open, in file order; empty for a whole or merely unclosed file.
    const std::vector<Damage>& damage() const { return mDamage; }
    // A scanned file's last chunk when the file ends inside it (a recording stopped while
    // writing it, or a cut copy): one line naming the file and offset; empty otherwise.
    const std::string& incompleteEnd() const { return mIncompleteEnd; }
    // Frames the file held that frames() lacks: those of an index found while scanning, else
    // the gaps a damaged stretch left in a context's frame numbers (a lower bound: frames
    // lost after a context's last readable one cannot be seen without an index).
    const std::vector<FrameId>& missingFrames() const { return mMissing; }
    // Blobs an index found while scanning lists that the scan did not find.
    uint64_t missingBlobs() const { return mMissingBlobs; }
    // Whether the frames the file held are known (from an index), so missingFrames() is all.
    bool knowsAllFrames() const { return !mRecovered || mSawIndex; }
    // The lines to say about the file when it is opened: each damaged stretch, an incomplete
    // end, and that the recording did not close it. Empty for a whole closed file.
    std::vector<std::string> notes() const;
    // Every note joined by "; " (empty when the file was whole).
    std::string warning() const;
    uint32_t version() const { return mVersion; }
    const std::string& path() const { return mPath; }

private:
    struct ChunkSpan; // a checked chunk header and where it lies

    bool openSource(std::string& error);
    void reset();
    bool readAt(uint64_t offset, void* dst, size_t size) const;
    std::string at(uint64_t offset, const std::string& message) const;
    // Checks that a whole chunk header, and the payload it declares, lie before limit.
    bool chunkAt(uint64_t offset, uint64_t limit, ChunkSpan& span, std::string& why) const;
    // Reads the payload in pieces to check the checksum without holding it all in memory.
    bool checksumMatches(const ChunkSpan& span, std::string& why) const;
    bool readPayload(const ChunkSpan& span, uint64_t maxSize, std::vector<uint8_t>& payload,
                     std::string& why) const;
    bool readMetadata(std::string& error);
    bool loadIndex(std::string& why);
    void scan();
    // Reads and records the whole chunk at offset; false with why when it is not one.
    bool takeChunk(uint64_t offset, ChunkSpan& span, std::string& why);
    // Whether [offset, end of file) can be the start of a chunk the file was cut inside.
    bool cutChunkAt(uint64_t offset) const;
    // The offset of the next whole chunk after `from` (a known type whose checksum holds),
    // or the file size when there is none.
    uint64_t nextChunk(uint64_t from) const;
    bool chunkIsWhole(uint64_t offset) const;
    void addDamage(uint64_t offset, uint64_t size, const std::string& message);
    void findMissingFrames();
    bool addBlob(const BlobInfo& blob);
    bool readBody(uint64_t offset, uint32_t type, uint64_t storedSize, uint64_t rawSize,
                  std::vector<uint8_t>& bodyHeader, std::vector<uint8_t>& out,
                  std::string& error) const;

    std::string mPath;
    int mFd = -1;
    std::vector<uint8_t> mMemory; // the file, for openMemory
    bool mInMemory = false;
    uint64_t mFileSize = 0;
    uint32_t mVersion = 0;
    uint64_t mFirstChunk = 0; // the chunk after META
    Metadata mMeta;
    std::vector<FrameInfo> mFrames;
    std::vector<BlobInfo> mBlobs;
    std::unordered_map<BlobHash, size_t> mBlobIndex;
    uint64_t mBlobBytes = 0;
    std::vector<std::pair<std::string, uint64_t>> mCallCounts;
    bool mRecovered = false;
    bool mClosed = false;
    std::vector<Damage> mDamage;
    std::string mIncompleteEnd;
    std::vector<FrameId> mIndexed; // the frames of an index found while scanning
    std::vector<BlobHash> mIndexedBlobs;   // and its blobs
    uint64_t mMissingBlobs = 0;
    bool mSawIndex = false;
    std::vector<FrameId> mMissing;
};

} // namespace nprgl::capture
