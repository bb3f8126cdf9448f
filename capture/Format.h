#pragma once

// The capture file layout shared by the writer, the reader, the tests and the fuzzer.
// docs/capture-format.md is the specification; keep the two in step.

#include "capture/ByteReader.h"
#include "capture/Metadata.h"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace nprgl::capture {

constexpr char kMagic[8] = {'N', 'P', 'R', 'G', 'L', 'C', 'A', 'P'};
// 2: META ends with the opcode name table; 3: frames may hold the Created pseudo-call (the name
// a created shader or program got), which a version 2 reader would refuse as unknown.
constexpr uint32_t kFormatVersion = 3;
constexpr uint64_t kFileHeaderSize = 16; // magic, u32 version, u32 flags (0)

constexpr uint32_t fourcc(const char (&s)[5])
{
    return uint32_t(uint8_t(s[0])) | uint32_t(uint8_t(s[1])) << 8 |
           uint32_t(uint8_t(s[2])) << 16 | uint32_t(uint8_t(s[3])) << 24;
}
constexpr uint32_t kChunkMeta = fourcc("META");
constexpr uint32_t kChunkBlob = fourcc("BLOB");
constexpr uint32_t kChunkFrame = fourcc("FRAM");
constexpr uint32_t kChunkCounts = fourcc("CNTS");
constexpr uint32_t kChunkIndex = fourcc("INDX");
constexpr uint32_t kChunkFooter = fourcc("FOOT");

// u32 type, u32 flags, u64 payload size, u64 checksum.
constexpr uint64_t kChunkHeaderSize = 24;
// FRAM: u32 context, u32 codec, u64 frame number, u64 raw size.
// BLOB: u64 hash, u64 raw size, u32 codec, u32 reserved.
constexpr uint64_t kBodyHeaderSize = 24;
constexpr uint64_t kFooterSize = kChunkHeaderSize + 8; // FOOT: u64 index offset
constexpr uint64_t kIndexHeaderSize = 24;              // u64 frames, u64 blobs, u64 counts at
constexpr uint64_t kIndexFrameSize = 40;
constexpr uint64_t kIndexBlobSize = 32;

constexpr uint32_t kCodecStored = 0;
constexpr uint32_t kCodecZstd = 1;

// Sanity limits a reader enforces before it allocates anything.
constexpr uint64_t kMaxRawSize = uint64_t(1) << 30;   // a frame or blob, uncompressed
constexpr uint32_t kMaxStringSize = uint32_t(1) << 20; // any string in META or CNTS
constexpr uint64_t kMaxSmallChunk = uint64_t(16) << 20; // META and CNTS payloads
// A zstd block (at most 128 KiB of output) costs at least 4 bytes, so no valid zstd data
// expands further than this; a larger declared raw size is a lie. (The other way, zstd data
// is never larger than ZSTD_COMPRESSBOUND of its content.)
constexpr uint64_t kMaxZstdRatio = 32768;

struct ChunkHeader {
    uint32_t type = 0;
    uint32_t flags = 0;
    uint64_t payloadSize = 0;
    uint64_t checksum = 0;
};

ChunkHeader parseChunkHeader(const uint8_t* p);
// XXH3_64bits of the first 16 bytes of the header (type, flags, size) followed by the payload.
uint64_t chunkChecksum(const uint8_t* header, const uint8_t* payload, size_t payloadSize);

// Appends a chunk header whose size and checksum finishChunk fills in once the payload that
// follows it has been appended. Returns where the chunk starts in out.
size_t beginChunk(std::vector<uint8_t>& out, uint32_t type);
void finishChunk(std::vector<uint8_t>& out, size_t start);

// "FRAM", or the hex value when the type is not printable.
std::string chunkTypeName(uint32_t type);
// Whether type is one of the chunk types that follow META.
bool knownChunkType(uint32_t type);
// "is a directory", "is a FIFO (named pipe)"...: what a stat mode that is not a regular file
// names; the reason a capture path is refused before it is opened for reading or writing.
std::string specialFileKind(unsigned mode);
// Whether a body of the given codec and stored size can hold rawSize bytes.
bool plausibleBody(uint32_t codec, uint64_t storedSize, uint64_t rawSize);

void encodeMetadata(const Metadata& meta, std::vector<uint8_t>& out);
// Reads META fields; ignores bytes after the known ones (room for later additions).
bool decodeMetadata(ByteReader& in, Metadata& meta);

using CallCounts = std::vector<std::pair<std::string, uint64_t>>;
void encodeCallCounts(const CallCounts& counts, std::vector<uint8_t>& out);
bool decodeCallCounts(ByteReader& in, CallCounts& counts);

} // namespace nprgl::capture
