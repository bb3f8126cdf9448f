// libFuzzer target for the capture reader: whatever the bytes, opening and reading must fail
// cleanly or return data that checks out, without crashing or allocating without bound.
// Built and run by scripts/fuzz.sh (clang, -fsanitize=fuzzer,address,undefined).

#include "capture/CaptureReader.h"
#include "capture/Format.h"
#include "capture/ReadReport.h"

#include <cstdint>
#include <string>
#include <vector>

using namespace nprgl::capture;

namespace {

void store64(uint8_t* p, uint64_t v)
{
    for (int i = 0; i < 8; ++i) p[i] = uint8_t(v >> (8 * i));
}

void exercise(const uint8_t* data, size_t size)
{
    CaptureReader reader;
    std::string error;
    if (!reader.openMemory(data, size, "fuzz.nprgl", error)) {
        if (error.empty()) __builtin_trap(); // a refusal must say why
        return;
    }
    std::vector<uint8_t> out;
    for (size_t i = 0; i < reader.frames().size(); ++i) {
        if (reader.readFrame(i, out, error) && out.size() != reader.frames()[i].rawSize)
            __builtin_trap();
    }
    uint64_t blobBytes = 0;
    for (const auto& blob : reader.blobs()) {
        blobBytes += blob.rawSize;
        if (reader.readBlob(blob.hash, out, error) && hashBlob(out.data(), out.size()) != blob.hash)
            __builtin_trap();
    }
    if (blobBytes != reader.blobBytes() || reader.fileBytes() != size) __builtin_trap();
    // Damage lies inside the file and is said with the file's name; so is an unclosed file.
    for (const auto& d : reader.damage()) {
        if (d.offset > size || d.size > size - d.offset) __builtin_trap();
        if (d.message.rfind("fuzz.nprgl: offset ", 0) != 0) __builtin_trap();
    }
    if (reader.recovered() && !reader.closed() && reader.notes().empty()) __builtin_trap();
    ReadReport report(reader);
    if (report.damaged() != !report.summary(reader.frames().size()).empty()) __builtin_trap();
}

// Random mutations almost never keep a checksum right, so most inputs would stop there.
// Rewriting every checksum lets them reach the decoders behind it. Returns whether any changed.
bool fixChecksums(std::vector<uint8_t>& file)
{
    bool changed = false;
    auto fix = [&](size_t at) {
        ChunkHeader h = parseChunkHeader(file.data() + at);
        uint64_t sum = chunkChecksum(file.data() + at, file.data() + at + kChunkHeaderSize,
                                     size_t(h.payloadSize));
        if (sum != h.checksum) {
            store64(file.data() + at + 16, sum);
            changed = true;
        }
    };
    size_t at = kFileHeaderSize;
    while (file.size() >= at && file.size() - at >= kChunkHeaderSize) {
        ChunkHeader h = parseChunkHeader(file.data() + at);
        if (h.payloadSize > file.size() - at - kChunkHeaderSize) break;
        fix(at);
        at += size_t(kChunkHeaderSize + h.payloadSize);
    }
    if (file.size() >= kFileHeaderSize + kFooterSize) {
        size_t footAt = file.size() - kFooterSize;
        ChunkHeader h = parseChunkHeader(file.data() + footAt);
        if (h.type == kChunkFooter && h.payloadSize == kFooterSize - kChunkHeaderSize)
            fix(footAt);
    }
    return changed;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    exercise(data, size);
    std::vector<uint8_t> fixed(data, data + size);
    if (fixChecksums(fixed)) exercise(fixed.data(), fixed.size());
    return 0;
}
