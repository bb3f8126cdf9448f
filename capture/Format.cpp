#include "capture/Format.h"

#include "capture/ByteWriter.h"

#define XXH_STATIC_LINKING_ONLY // XXH3_state_t on the stack
#include <xxhash.h>
#include <zstd.h>

#include <cstdio>
#include <cstring>

#include <sys/stat.h>

namespace nprgl::capture {

namespace {

uint64_t load64(const uint8_t* p)
{
    uint64_t v = 0;
    for (int i = 0; i < 8; ++i) v |= uint64_t(p[i]) << (8 * i);
    return v;
}

uint32_t load32(const uint8_t* p)
{
    return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

void store64(uint8_t* p, uint64_t v)
{
    for (int i = 0; i < 8; ++i) p[i] = uint8_t(v >> (8 * i));
}

// A count is only believable when each counted item, at its smallest, still fits.
bool countFits(ByteReader& in, uint64_t count, uint64_t minItemSize, const char* what)
{
    if (count <= in.remaining() / minItemSize) return true;
    in.fail(in.fileOffset() - 4, std::string(what) + " count " + std::to_string(count) +
                                     " cannot fit in the " + std::to_string(in.remaining()) +
                                     " bytes left in its chunk");
    return false;
}

} // namespace

BlobHash hashBlob(const void* data, size_t size)
{
    return XXH3_64bits(data, size);
}

ChunkHeader parseChunkHeader(const uint8_t* p)
{
    return ChunkHeader{load32(p), load32(p + 4), load64(p + 8), load64(p + 16)};
}

uint64_t chunkChecksum(const uint8_t* header, const uint8_t* payload, size_t payloadSize)
{
    XXH3_state_t state;
    XXH3_INITSTATE(&state);
    XXH3_64bits_reset(&state);
    XXH3_64bits_update(&state, header, 16);
    XXH3_64bits_update(&state, payload, payloadSize);
    return XXH3_64bits_digest(&state);
}

size_t beginChunk(std::vector<uint8_t>& out, uint32_t type)
{
    size_t start = out.size();
    ByteWriter w(out);
    w.u32(type);
    w.u32(0);
    w.u64(0);
    w.u64(0);
    return start;
}

void finishChunk(std::vector<uint8_t>& out, size_t start)
{
    uint8_t* chunk = out.data() + start;
    uint64_t payloadSize = out.size() - start - kChunkHeaderSize;
    store64(chunk + 8, payloadSize);
    store64(chunk + 16, chunkChecksum(chunk, chunk + kChunkHeaderSize, payloadSize));
}

std::string chunkTypeName(uint32_t type)
{
    std::string name;
    for (int i = 0; i < 4; ++i) {
        char c = char(type >> (8 * i));
        if (c < 0x20 || c > 0x7e) {
            char hex[16];
            std::snprintf(hex, sizeof hex, "0x%08x", type);
            return hex;
        }
        name += c;
    }
    return name;
}

bool knownChunkType(uint32_t type)
{
    return type == kChunkFrame || type == kChunkBlob || type == kChunkCounts ||
           type == kChunkIndex || type == kChunkFooter;
}

std::string specialFileKind(unsigned mode)
{
    if (S_ISDIR(mode)) return "is a directory";
    if (S_ISFIFO(mode)) return "is a FIFO (named pipe)";
    if (S_ISCHR(mode)) return "is a character device";
    if (S_ISBLK(mode)) return "is a block device";
    if (S_ISSOCK(mode)) return "is a socket";
    return "is not a regular file";
}

bool plausibleBody(uint32_t codec, uint64_t storedSize, uint64_t rawSize)
{
    if (rawSize > kMaxRawSize) return false;
    if (codec == kCodecStored) return storedSize == rawSize;
    // Divides rather than multiplies: storedSize comes from the file and may be huge.
    if (codec == kCodecZstd)
        return (rawSize + kMaxZstdRatio - 1) / kMaxZstdRatio <= storedSize &&
               storedSize <= ZSTD_COMPRESSBOUND(rawSize);
    return false;
}

void encodeMetadata(const Metadata& meta, std::vector<uint8_t>& out)
{
    ByteWriter w(out);
    w.string(meta.program);
    w.u32(uint32_t(meta.commandLine.size()));
    for (const std::string& arg : meta.commandLine) w.string(arg);
    w.string(meta.glVendor);
    w.string(meta.glRenderer);
    w.string(meta.glVersion);
    w.u32(uint32_t(meta.width));
    w.u32(uint32_t(meta.height));
    w.u32(meta.pid);
    w.u64(meta.startTimeUnix);
    w.u32(uint32_t(meta.extra.size()));
    for (const auto& [key, value] : meta.extra) {
        w.string(key);
        w.string(value);
    }
    w.u32(uint32_t(meta.opcodeNames.size()));
    for (const std::string& name : meta.opcodeNames) w.string(name);
}

bool decodeMetadata(ByteReader& in, Metadata& meta)
{
    Metadata m;
    m.program = in.string(kMaxStringSize, "program name");
    uint32_t argc = in.u32();
    if (in.ok() && countFits(in, argc, 4, "command line argument")) {
        for (uint32_t i = 0; i < argc && in.ok(); ++i)
            m.commandLine.push_back(in.string(kMaxStringSize, "command line argument"));
    }
    m.glVendor = in.string(kMaxStringSize, "GL vendor");
    m.glRenderer = in.string(kMaxStringSize, "GL renderer");
    m.glVersion = in.string(kMaxStringSize, "GL version");
    m.width = int(int32_t(in.u32()));
    m.height = int(int32_t(in.u32()));
    m.pid = in.u32();
    m.startTimeUnix = in.u64();
    uint32_t extras = in.u32();
    if (in.ok() && countFits(in, extras, 8, "extra key/value")) {
        for (uint32_t i = 0; i < extras && in.ok(); ++i) {
            std::string key = in.string(kMaxStringSize, "extra key");
            std::string value = in.string(kMaxStringSize, "extra value");
            m.extra.emplace_back(std::move(key), std::move(value));
        }
    }
    // Version 1 ends here (a reader ignores what it does not know after the known fields).
    if (in.ok() && in.remaining() > 0) {
        uint32_t names = in.u32();
        if (in.ok() && countFits(in, names, 4, "opcode name")) {
            for (uint32_t i = 0; i < names && in.ok(); ++i)
                m.opcodeNames.push_back(in.string(kMaxStringSize, "opcode name"));
        }
    }
    if (!in.ok()) return false;
    meta = std::move(m);
    return true;
}

void encodeCallCounts(const CallCounts& counts, std::vector<uint8_t>& out)
{
    ByteWriter w(out);
    w.u32(uint32_t(counts.size()));
    for (const auto& [name, count] : counts) {
        w.string(name);
        w.u64(count);
    }
}

bool decodeCallCounts(ByteReader& in, CallCounts& counts)
{
    CallCounts c;
    uint32_t n = in.u32();
    if (in.ok() && countFits(in, n, 12, "call name")) {
        for (uint32_t i = 0; i < n && in.ok(); ++i) {
            std::string name = in.string(kMaxStringSize, "call name");
            uint64_t count = in.u64();
            c.emplace_back(std::move(name), count);
        }
    }
    if (!in.ok()) return false;
    counts = std::move(c);
    return true;
}

} // namespace nprgl::capture
