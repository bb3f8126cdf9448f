#include "capture/CaptureReader.h"

#include "capture/ByteReader.h"
#include "capture/Format.h"

#define XXH_STATIC_LINKING_ONLY // XXH3_state_t on the stack
#include <xxhash.h>
#include <zstd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <map>
#include <set>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace nprgl::capture {

struct CaptureReader::ChunkSpan {
    uint64_t offset = 0;
    ChunkHeader header;
    uint8_t raw[kChunkHeaderSize] = {};

    uint64_t payloadOffset() const { return offset + kChunkHeaderSize; }
    uint64_t end() const { return offset + kChunkHeaderSize + header.payloadSize; }
};

namespace {

// The checksum of a large chunk is computed in pieces of this size.
constexpr size_t kChecksumPiece = size_t(1) << 20;

uint32_t load32(const uint8_t* p)
{
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

uint64_t load64(const uint8_t* p)
{
    return uint64_t(load32(p)) | uint64_t(load32(p + 4)) << 32;
}

std::string quoted(uint32_t type)
{
    return "'" + chunkTypeName(type) + "'";
}

} // namespace

CaptureReader::~CaptureReader()
{
    reset();
}

bool CaptureReader::open(const std::string& path, std::string& error)
{
    reset();
    mPath = path;
    try {
        // Looked at before it is opened: opening a FIFO waits for a writer, and a device may
        // do something when opened. O_NONBLOCK covers a file swapped in between.
        struct stat st;
        if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
            error = path + ": " + specialFileKind(st.st_mode) + ", not a capture file";
            reset();
            return false;
        }
        int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
        if (fd < 0) {
            error = path + ": cannot open: " + std::strerror(errno);
            reset();
            return false;
        }
        mFd = fd;
        if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
            error = path + ": " + specialFileKind(st.st_mode) + ", not a capture file";
            reset();
            return false;
        }
        mFileSize = uint64_t(st.st_size);
        if (openSource(error)) return true;
    } catch (const std::exception& e) {
        error = path + ": cannot read: " + e.what();
    }
    reset();
    return false;
}

bool CaptureReader::openMemory(const void* data, size_t size, const std::string& name,
                               std::string& error)
{
    reset();
    mPath = name;
    try {
        const uint8_t* bytes = static_cast<const uint8_t*>(data);
        mMemory.assign(bytes, bytes + size);
        mInMemory = true;
        mFileSize = size;
        if (openSource(error)) return true;
    } catch (const std::exception& e) {
        error = name + ": cannot read: " + e.what();
    }
    reset();
    return false;
}

bool CaptureReader::openSource(std::string& error)
{
    if (mFileSize == 0) {
        error = at(0, "empty file, not an nprgl capture");
        return false;
    }
    if (mFileSize < kFileHeaderSize) {
        error = at(0, "file is " + std::to_string(mFileSize) + " bytes, too short for the " +
                          std::to_string(kFileHeaderSize) + "-byte header");
        return false;
    }
    uint8_t head[kFileHeaderSize];
    if (!readAt(0, head, sizeof head)) {
        error = at(0, std::string("cannot read the header: ") + std::strerror(errno));
        return false;
    }
    if (std::memcmp(head, kMagic, sizeof kMagic) != 0) {
        error = at(0, "not an nprgl capture (bad magic)");
        return false;
    }
    mVersion = load32(head + 8);
    if (mVersion > kFormatVersion) {
        error = at(8, "format version " + std::to_string(mVersion) + " is newer than this " +
                          "reader understands (" + std::to_string(kFormatVersion) +
                          "); use a newer nprgl");
        return false;
    }
    if (mVersion == 0) {
        error = at(8, "bad format version 0");
        return false;
    }
    if (uint32_t flags = load32(head + 12)) {
        error = at(12, "unknown header flags " + std::to_string(flags) + " (expected 0)");
        return false;
    }
    if (!readMetadata(error)) return false;

    std::string why;
    if (!loadIndex(why)) {
        mFrames.clear();
        mBlobs.clear();
        mBlobIndex.clear();
        mBlobBytes = 0;
        mCallCounts.clear();
        if (!why.empty()) {
            addDamage(mFileSize - kFooterSize, 0,
                      why + "; the index is unusable: the file was read by scanning instead");
        }
        scan();
    }
    return true;
}

void CaptureReader::reset()
{
    if (mFd >= 0) ::close(mFd);
    mFd = -1;
    mPath.clear();
    std::vector<uint8_t>().swap(mMemory);
    mInMemory = false;
    mFileSize = 0;
    mVersion = 0;
    mFirstChunk = 0;
    mMeta = Metadata();
    mFrames.clear();
    mBlobs.clear();
    mBlobIndex.clear();
    mBlobBytes = 0;
    mCallCounts.clear();
    mRecovered = false;
    mClosed = false;
    mDamage.clear();
    mIncompleteEnd.clear();
    mIndexed.clear();
    mIndexedBlobs.clear();
    mSawIndex = false;
    mMissing.clear();
    mMissingBlobs = 0;
}

bool CaptureReader::readAt(uint64_t offset, void* dst, size_t size) const
{
    if (offset > mFileSize || size > mFileSize - offset) return false;
    if (mInMemory) {
        if (size > 0) std::memcpy(dst, mMemory.data() + offset, size);
        return true;
    }
    uint8_t* out = static_cast<uint8_t*>(dst);
    while (size > 0) {
        ssize_t n = ::pread(mFd, out, size, off_t(offset));
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false; // an error, or the file shrank since open
        out += n;
        offset += uint64_t(n);
        size -= size_t(n);
    }
    return true;
}

std::string CaptureReader::at(uint64_t offset, const std::string& message) const
{
    return mPath + ": offset " + std::to_string(offset) + ": " + message;
}

bool CaptureReader::chunkAt(uint64_t offset, uint64_t limit, ChunkSpan& span,
                            std::string& why) const
{
    if (offset > limit || limit - offset < kChunkHeaderSize) {
        why = "the file ends inside a chunk header (" +
              std::to_string(offset > limit ? 0 : limit - offset) + " bytes left)";
        return false;
    }
    if (!readAt(offset, span.raw, kChunkHeaderSize)) {
        why = "cannot read a chunk header";
        return false;
    }
    span.offset = offset;
    span.header = parseChunkHeader(span.raw);
    uint64_t room = limit - offset - kChunkHeaderSize;
    if (span.header.payloadSize > room) {
        why = "chunk length " + std::to_string(span.header.payloadSize) + " runs past ";
        why += limit == mFileSize
                   ? "the end of the file (" + std::to_string(mFileSize) + " bytes)"
                   : "offset " + std::to_string(limit) + ", where the next structure starts";
        return false;
    }
    return true;
}

bool CaptureReader::checksumMatches(const ChunkSpan& span, std::string& why) const
{
    XXH3_state_t state;
    XXH3_INITSTATE(&state);
    XXH3_64bits_reset(&state);
    XXH3_64bits_update(&state, span.raw, 16);
    std::vector<uint8_t> piece(size_t(std::min<uint64_t>(span.header.payloadSize, kChecksumPiece)));
    for (uint64_t done = 0; done < span.header.payloadSize;) {
        size_t n = size_t(std::min<uint64_t>(span.header.payloadSize - done, piece.size()));
        if (!readAt(span.payloadOffset() + done, piece.data(), n)) {
            why = "cannot read the chunk";
            return false;
        }
        XXH3_64bits_update(&state, piece.data(), n);
        done += n;
    }
    if (XXH3_64bits_digest(&state) != span.header.checksum) {
        why = "checksum mismatch in " + quoted(span.header.type) + " chunk (damaged file)";
        return false;
    }
    return true;
}

bool CaptureReader::readPayload(const ChunkSpan& span, uint64_t maxSize,
                                std::vector<uint8_t>& payload, std::string& why) const
{
    if (span.header.payloadSize > maxSize) {
        why = quoted(span.header.type) + " chunk of " + std::to_string(span.header.payloadSize) +
              " bytes is over the limit of " + std::to_string(maxSize);
        return false;
    }
    payload.resize(size_t(span.header.payloadSize));
    if (!readAt(span.payloadOffset(), payload.data(), payload.size())) {
        why = "cannot read the chunk";
        return false;
    }
    if (chunkChecksum(span.raw, payload.data(), payload.size()) != span.header.checksum) {
        why = "checksum mismatch in " + quoted(span.header.type) + " chunk (damaged file)";
        return false;
    }
    return true;
}

bool CaptureReader::readMetadata(std::string& error)
{
    ChunkSpan span;
    std::vector<uint8_t> payload;
    std::string why;
    if (!chunkAt(kFileHeaderSize, mFileSize, span, why)) {
        error = at(kFileHeaderSize, why);
        return false;
    }
    if (span.header.type != kChunkMeta) {
        error = at(kFileHeaderSize,
                   "expected the metadata chunk 'META', found " + quoted(span.header.type));
        return false;
    }
    if (!readPayload(span, kMaxSmallChunk, payload, why)) {
        error = at(kFileHeaderSize, why);
        return false;
    }
    ByteReader in(payload.data(), payload.size(), span.payloadOffset());
    if (!decodeMetadata(in, mMeta)) {
        error = at(in.errorOffset(), in.error());
        return false;
    }
    mFirstChunk = span.end();
    return true;
}

bool CaptureReader::loadIndex(std::string& why)
{
    // No footer means the program stopped before close(): not an error, just a scan.
    if (mFileSize - mFirstChunk < kFooterSize) return false;
    uint64_t footAt = mFileSize - kFooterSize;
    ChunkSpan foot;
    std::string detail;
    if (!chunkAt(footAt, mFileSize, foot, detail) || foot.header.type != kChunkFooter) return false;
    std::vector<uint8_t> payload;
    if (foot.header.payloadSize != kFooterSize - kChunkHeaderSize) {
        why = at(footAt, "footer of " + std::to_string(foot.header.payloadSize) +
                             " bytes, expected 8");
        return false;
    }
    if (!readPayload(foot, 8, payload, detail)) {
        why = at(footAt, detail);
        return false;
    }
    mClosed = true; // a footer whose checksum holds: whatever is wrong now is damage
    uint64_t indexAt = load64(payload.data());
    ChunkSpan index;
    if (indexAt < mFirstChunk || indexAt > footAt) {
        why = at(foot.payloadOffset(), "index offset " + std::to_string(indexAt) +
                                           " lies outside the chunks (" +
                                           std::to_string(mFirstChunk) + " to " +
                                           std::to_string(footAt) + ")");
        return false;
    }
    if (!chunkAt(indexAt, footAt, index, detail)) {
        why = at(indexAt, detail);
        return false;
    }
    if (index.header.type != kChunkIndex) {
        why = at(indexAt, "expected the index chunk 'INDX', found " + quoted(index.header.type));
        return false;
    }
    if (index.end() != footAt) {
        why = at(index.end(), std::to_string(footAt - index.end()) +
                                  " stray bytes between the index and the footer");
        return false;
    }
    if (!readPayload(index, footAt, payload, detail)) {
        why = at(indexAt, detail);
        return false;
    }

    ByteReader in(payload.data(), payload.size(), index.payloadOffset());
    uint64_t frameCount = in.u64();
    uint64_t blobCount = in.u64();
    uint64_t countsAt = in.u64();
    if (in.ok() && frameCount > in.remaining() / kIndexFrameSize)
        in.fail(index.payloadOffset(), "index frame count " + std::to_string(frameCount) +
                                           " cannot fit in its chunk");
    if (in.ok() && blobCount > (in.remaining() - frameCount * kIndexFrameSize) / kIndexBlobSize)
        in.fail(index.payloadOffset() + 8, "index blob count " + std::to_string(blobCount) +
                                               " cannot fit in its chunk");
    if (!in.ok()) {
        why = at(in.errorOffset(), in.error());
        return false;
    }
    // A chunk the index points at must lie between the metadata and the index.
    auto inChunks = [&](uint64_t offset, uint64_t storedSize) {
        uint64_t minimum = kChunkHeaderSize + kBodyHeaderSize;
        return offset >= mFirstChunk && offset <= indexAt && indexAt - offset >= minimum &&
               storedSize <= indexAt - offset - minimum;
    };
    mFrames.reserve(size_t(frameCount));
    for (uint64_t i = 0; i < frameCount; ++i) {
        uint64_t entryAt = in.fileOffset();
        FrameInfo f{};
        f.offset = in.u64();
        f.contextId = in.u32();
        in.u32();
        f.frameNumber = in.u64();
        f.compressedSize = in.u64();
        f.rawSize = in.u64();
        if (!inChunks(f.offset, f.compressedSize) ||
            !(plausibleBody(kCodecStored, f.compressedSize, f.rawSize) ||
              plausibleBody(kCodecZstd, f.compressedSize, f.rawSize))) {
            why = at(entryAt, "index entry of frame " + std::to_string(i) + " (chunk at " +
                                  std::to_string(f.offset) + ", " +
                                  std::to_string(f.compressedSize) + " bytes stored, " +
                                  std::to_string(f.rawSize) + " raw) is impossible");
            return false;
        }
        mFrames.push_back(f);
    }
    mBlobs.reserve(size_t(blobCount));
    for (uint64_t i = 0; i < blobCount; ++i) {
        uint64_t entryAt = in.fileOffset();
        BlobInfo b{};
        b.hash = in.u64();
        b.offset = in.u64();
        b.compressedSize = in.u64();
        b.rawSize = in.u64();
        if (!inChunks(b.offset, b.compressedSize) ||
            !(plausibleBody(kCodecStored, b.compressedSize, b.rawSize) ||
              plausibleBody(kCodecZstd, b.compressedSize, b.rawSize))) {
            why = at(entryAt, "index entry of blob " + std::to_string(i) + " is impossible");
            return false;
        }
        addBlob(b);
    }
    if (countsAt != 0) {
        ChunkSpan counts;
        if (countsAt < mFirstChunk || !chunkAt(countsAt, indexAt, counts, detail) ||
            counts.header.type != kChunkCounts ||
            !readPayload(counts, kMaxSmallChunk, payload, detail)) {
            why = at(countsAt, "the index points at no valid call count chunk" +
                                   (detail.empty() ? "" : " (" + detail + ")"));
            return false;
        }
        ByteReader countsIn(payload.data(), payload.size(), counts.payloadOffset());
        if (!decodeCallCounts(countsIn, mCallCounts)) {
            why = at(countsIn.errorOffset(), countsIn.error());
            return false;
        }
    }
    return true;
}

void CaptureReader::scan()
{
    mRecovered = true;
    uint64_t offset = mFirstChunk;
    while (offset < mFileSize) {
        ChunkSpan span;
        std::string why;
        if (takeChunk(offset, span, why)) {
            offset = span.end();
            continue;
        }
        const uint64_t next = nextChunk(offset);
        const uint64_t skipped = next - offset;
        if (next == mFileSize && cutChunkAt(offset)) {
            mIncompleteEnd = at(offset, "the file ends inside a chunk (" + why + "): its last " +
                                            std::to_string(skipped) + " bytes are an " +
                                            "incomplete chunk, cut off as it was written");
            break;
        }
        addDamage(offset, skipped,
                  why + "; " +
                      (next == mFileSize
                           ? "nothing readable follows (" + std::to_string(skipped) +
                                 " bytes to the end of the file)"
                           : "skipped " + std::to_string(skipped) +
                                 " bytes to the next whole chunk at offset " +
                                 std::to_string(next)));
        offset = next;
    }
    findMissingFrames();
}

bool CaptureReader::takeChunk(uint64_t offset, ChunkSpan& span, std::string& why)
{
    if (!chunkAt(offset, mFileSize, span, why) || !checksumMatches(span, why)) return false;
    std::vector<uint8_t> payload;
    uint8_t body[kBodyHeaderSize];
    const uint32_t type = span.header.type;
    const uint64_t stored = span.header.payloadSize - kBodyHeaderSize;
    if (type == kChunkFrame || type == kChunkBlob) {
        if (span.header.payloadSize < kBodyHeaderSize ||
            !readAt(span.payloadOffset(), body, sizeof body)) {
            why = quoted(type) + " chunk too short for its header";
            return false;
        }
    }
    if (type == kChunkFrame) {
        FrameInfo f{load32(body), load64(body + 8), offset, stored, load64(body + 16)};
        if (!plausibleBody(load32(body + 4), stored, f.rawSize)) {
            why = "impossible frame sizes or codec";
            return false;
        }
        mFrames.push_back(f);
    } else if (type == kChunkBlob) {
        BlobInfo b{load64(body), offset, stored, load64(body + 8)};
        if (!plausibleBody(load32(body + 16), stored, b.rawSize)) {
            why = "impossible blob sizes or codec";
            return false;
        }
        addBlob(b);
    } else if (type == kChunkCounts) {
        CallCounts counts;
        if (!readPayload(span, kMaxSmallChunk, payload, why)) return false;
        ByteReader in(payload.data(), payload.size(), span.payloadOffset());
        if (!decodeCallCounts(in, counts)) {
            why = in.error();
            return false;
        }
        mCallCounts = std::move(counts);
    } else if (type == kChunkIndex) {
        // Not used for offsets (the file is being scanned because they may be wrong), only
        // to know which frames the file held.
        if (!readPayload(span, mFileSize, payload, why)) return false;
        ByteReader in(payload.data(), payload.size(), span.payloadOffset());
        const uint64_t frameCount = in.u64();
        const uint64_t blobCount = in.u64();
        in.u64();
        if (!in.ok() || frameCount > in.remaining() / kIndexFrameSize ||
            blobCount > (in.remaining() - frameCount * kIndexFrameSize) / kIndexBlobSize) {
            why = "index counts cannot fit in its chunk";
            return false;
        }
        mIndexed.clear();
        for (uint64_t i = 0; i < frameCount; ++i) {
            in.u64();
            FrameId id{in.u32(), 0};
            in.u32();
            id.frameNumber = in.u64();
            in.u64();
            in.u64();
            mIndexed.push_back(id);
        }
        mIndexedBlobs.clear();
        for (uint64_t i = 0; i < blobCount; ++i) {
            mIndexedBlobs.push_back(in.u64());
            in.u64();
            in.u64();
            in.u64();
        }
        mSawIndex = true;
    } else if (type == kChunkFooter) {
        mClosed = true;
    }
    // Chunk kinds added later are skipped.
    return true;
}

bool CaptureReader::cutChunkAt(uint64_t offset) const
{
    const uint64_t left = mFileSize - offset;
    uint8_t head[kChunkHeaderSize] = {};
    if (left < 4) return true;
    if (!readAt(offset, head, size_t(std::min<uint64_t>(left, kChunkHeaderSize)))) return false;
    if (!knownChunkType(load32(head))) return false;
    if (left >= 8 && load32(head + 4) != 0) return false;
    if (left < kChunkHeaderSize) return true;
    // A whole header: it must promise more than the file holds, and no absurd amount.
    const uint64_t size = load64(head + 8);
    return size > left - kChunkHeaderSize && size <= 2 * kMaxRawSize;
}

bool CaptureReader::chunkIsWhole(uint64_t offset) const
{
    ChunkSpan span;
    std::string why;
    if (!chunkAt(offset, mFileSize, span, why) || !knownChunkType(span.header.type) ||
        span.header.flags != 0 || !checksumMatches(span, why)) {
        return false;
    }
    const uint32_t type = span.header.type;
    if (type != kChunkFrame && type != kChunkBlob) return true;
    uint8_t body[kBodyHeaderSize];
    if (span.header.payloadSize < kBodyHeaderSize ||
        !readAt(span.payloadOffset(), body, sizeof body)) {
        return false;
    }
    const uint64_t stored = span.header.payloadSize - kBodyHeaderSize;
    return type == kChunkFrame ? plausibleBody(load32(body + 4), stored, load64(body + 16))
                               : plausibleBody(load32(body + 16), stored, load64(body + 8));
}

uint64_t CaptureReader::nextChunk(uint64_t from) const
{
    // Read in windows; a candidate is a known type followed by zero flags, and only those
    // are checked whole (their checksum read).
    constexpr size_t kWindow = size_t(1) << 16;
    std::vector<uint8_t> window(kWindow + 8);
    for (uint64_t base = from + 1; base + kChunkHeaderSize <= mFileSize; base += kWindow) {
        const size_t n = size_t(std::min<uint64_t>(kWindow + 8, mFileSize - base));
        if (!readAt(base, window.data(), n)) return mFileSize;
        for (size_t i = 0; i + 8 <= n && i < kWindow; ++i) {
            if (load32(window.data() + i + 4) != 0 || !knownChunkType(load32(window.data() + i)))
                continue;
            if (chunkIsWhole(base + i)) return base + i;
        }
    }
    return mFileSize;
}

void CaptureReader::addDamage(uint64_t offset, uint64_t size, const std::string& message)
{
    // Messages from loadIndex already name the file and offset.
    const bool named = message.compare(0, mPath.size() + 2, mPath + ": ") == 0;
    mDamage.push_back(Damage{offset, size, named ? message : at(offset, message)});
}

void CaptureReader::findMissingFrames()
{
    mMissing.clear();
    mMissingBlobs = 0;
    std::map<uint32_t, std::set<uint64_t>> found;
    for (const FrameInfo& f : mFrames) found[f.contextId].insert(f.frameNumber);
    if (mSawIndex) {
        for (const FrameId& id : mIndexed) {
            auto it = found.find(id.contextId);
            if (it == found.end() || !it->second.count(id.frameNumber)) mMissing.push_back(id);
        }
        for (BlobHash hash : mIndexedBlobs) mMissingBlobs += !hasBlob(hash);
        return;
    }
    if (mDamage.empty()) return;
    // Without an index, a context's frames are numbered one after another: a gap is a loss.
    // Each lost frame took a chunk of the skipped bytes, which bounds the count.
    uint64_t skipped = 0;
    for (const Damage& d : mDamage) skipped += d.size;
    uint64_t budget = skipped / (kChunkHeaderSize + kBodyHeaderSize) + 1;
    for (const auto& [context, numbers] : found) {
        uint64_t previous = 0;
        bool first = true;
        for (uint64_t n : numbers) {
            for (uint64_t m = previous + 1; !first && m < n && budget > 0; ++m, --budget)
                mMissing.push_back(FrameId{context, m});
            previous = n;
            first = false;
        }
    }
}

std::vector<std::string> CaptureReader::notes() const
{
    std::vector<std::string> lines;
    for (const Damage& d : mDamage) lines.push_back(d.message);
    if (!mIncompleteEnd.empty()) lines.push_back(mIncompleteEnd);
    if (mRecovered && !mClosed) {
        lines.push_back(mPath + ": not closed by its recording (no index at its end): " +
                        std::to_string(mFrames.size()) + " frame" +
                        (mFrames.size() == 1 ? "" : "s") + " found by scanning");
    }
    return lines;
}

std::string CaptureReader::warning() const
{
    std::string joined;
    for (const std::string& line : notes()) joined += (joined.empty() ? "" : "; ") + line;
    return joined;
}

bool CaptureReader::addBlob(const BlobInfo& blob)
{
    if (!mBlobIndex.emplace(blob.hash, mBlobs.size()).second) return false;
    mBlobs.push_back(blob);
    mBlobBytes += blob.rawSize;
    return true;
}

bool CaptureReader::readBody(uint64_t offset, uint32_t type, uint64_t storedSize,
                             uint64_t rawSize, std::vector<uint8_t>& bodyHeader,
                             std::vector<uint8_t>& out, std::string& error) const
{
    // The sizes were checked against the file when the index was loaded or scanned.
    uint64_t payloadSize = kBodyHeaderSize + storedSize;
    std::vector<uint8_t> chunk(size_t(kChunkHeaderSize + payloadSize));
    if (!readAt(offset, chunk.data(), chunk.size())) {
        error = at(offset, "cannot read the chunk (was the file changed?)");
        return false;
    }
    ChunkHeader h = parseChunkHeader(chunk.data());
    if (h.type != type) {
        error = at(offset, "expected a " + quoted(type) + " chunk, found " + quoted(h.type));
        return false;
    }
    if (h.payloadSize != payloadSize) {
        error = at(offset, "chunk length " + std::to_string(h.payloadSize) +
                               " differs from the index (" + std::to_string(payloadSize) + ")");
        return false;
    }
    const uint8_t* payload = chunk.data() + kChunkHeaderSize;
    if (chunkChecksum(chunk.data(), payload, size_t(payloadSize)) != h.checksum) {
        error = at(offset, "checksum mismatch in " + quoted(type) + " chunk (damaged file)");
        return false;
    }
    bodyHeader.assign(payload, payload + kBodyHeaderSize);
    bool frame = type == kChunkFrame;
    uint32_t codec = load32(payload + (frame ? 4 : 16));
    uint64_t declaredRaw = load64(payload + (frame ? 16 : 8));
    if (declaredRaw != rawSize || !plausibleBody(codec, storedSize, rawSize)) {
        error = at(offset, quoted(type) + " chunk declares " + std::to_string(declaredRaw) +
                               " raw bytes with codec " + std::to_string(codec) +
                               ", which does not fit the " + std::to_string(storedSize) +
                               " stored bytes or the index (" + std::to_string(rawSize) + ")");
        return false;
    }
    const uint8_t* data = payload + kBodyHeaderSize;
    out.resize(size_t(rawSize));
    if (codec == kCodecStored) {
        if (rawSize > 0) std::memcpy(out.data(), data, size_t(rawSize));
        return true;
    }
    size_t n = ZSTD_decompress(out.data(), out.size(), data, size_t(storedSize));
    if (ZSTD_isError(n) || n != rawSize) {
        error = at(offset + kChunkHeaderSize + kBodyHeaderSize,
                   std::string("data does not decompress to the declared ") +
                       std::to_string(rawSize) + " bytes" +
                       (ZSTD_isError(n) ? std::string(" (zstd: ") + ZSTD_getErrorName(n) + ")"
                                        : ""));
        out.clear();
        return false;
    }
    return true;
}

bool CaptureReader::readFrame(size_t index, std::vector<uint8_t>& calls,
                              std::string& error) const
{
    calls.clear();
    if (index >= mFrames.size()) {
        error = mPath + ": frame " + std::to_string(index) + " does not exist (the capture has " +
                std::to_string(mFrames.size()) + ")";
        return false;
    }
    const FrameInfo& f = mFrames[index];
    try {
        std::vector<uint8_t> body;
        if (!readBody(f.offset, kChunkFrame, f.compressedSize, f.rawSize, body, calls, error))
            return false;
        if (load32(body.data()) != f.contextId || load64(body.data() + 8) != f.frameNumber) {
            calls.clear();
            error = at(f.offset, "frame chunk's context or frame number differs from the index");
            return false;
        }
        return true;
    } catch (const std::exception& e) {
        calls.clear();
        error = at(f.offset, std::string("cannot read frame ") + std::to_string(index) + ": " +
                                 e.what());
        return false;
    }
}

bool CaptureReader::readBlob(BlobHash hash, std::vector<uint8_t>& out, std::string& error) const
{
    out.clear();
    auto it = mBlobIndex.find(hash);
    if (it == mBlobIndex.end()) {
        char hex[32];
        std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
        error = mPath + ": no blob with hash " + hex;
        return false;
    }
    const BlobInfo& b = mBlobs[it->second];
    try {
        std::vector<uint8_t> body;
        if (!readBody(b.offset, kChunkBlob, b.compressedSize, b.rawSize, body, out, error))
            return false;
        if (load64(body.data()) != hash || hashBlob(out.data(), out.size()) != hash) {
            out.clear();
            error = at(b.offset, "blob content does not match its hash");
            return false;
        }
        return true;
    } catch (const std::exception& e) {
        out.clear();
        error = at(b.offset, std::string("cannot read a blob: ") + e.what());
        return false;
    }
}

} // namespace nprgl::capture
