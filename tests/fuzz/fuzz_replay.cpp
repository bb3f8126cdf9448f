// libFuzzer target for the replayer: a capture whose container is valid (the target builds it
// with CaptureWriter) and whose calls are whatever the fuzzer made them, decoded and replayed
// into an OSMesa context through the shim's dispatch. Nothing may crash, hang or allocate
// without bound; a bad call must be refused with a message.
// Built by scripts/fuzz.sh (CMake, NPRGL_FUZZ=ON, clang); the style is NPRGL_STYLE's.
//
// Input: one byte choosing the frame size, then sections [u8 kind][u16 length][bytes]:
// kind even, the calls of one frame; odd, a blob. In frames, the 8 bytes "\xB1\x0B" x3,
// "\xB1", k stand for the hash of blob k (k modulo the blob count), so that references stay
// valid while the fuzzer mutates the blobs (make_replay_seeds writes such inputs).

#include "capture/CaptureWriter.h"
#include "replay/Replayer.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <unistd.h>
#include <vector>

using namespace nprgl;

namespace {

constexpr uint8_t kBlobToken[7] = {0xB1, 0x0B, 0xB1, 0x0B, 0xB1, 0x0B, 0xB1};

std::string gPath;
const bool gVerbose = std::getenv("NPRGL_FUZZ_VERBOSE") != nullptr; // print refusals

void resolveBlobTokens(std::vector<uint8_t>& calls, const std::vector<capture::BlobHash>& hashes)
{
    if (hashes.empty() || calls.size() < 8) return;
    for (size_t i = 0; i + 8 <= calls.size(); ++i) {
        if (std::memcmp(calls.data() + i, kBlobToken, sizeof kBlobToken) != 0) continue;
        const capture::BlobHash h = hashes[calls[i + 7] % hashes.size()];
        std::memcpy(calls.data() + i, &h, 8); // little-endian, as CallWriter writes it
        i += 7;
    }
}

bool writeCapture(const uint8_t* data, size_t size, int& width, int& height)
{
    if (size < 1) return false;
    width = 16 + 8 * (data[0] & 3);
    height = 16 + 8 * ((data[0] >> 2) & 3);
    struct Section {
        bool blob;
        std::vector<uint8_t> bytes;
    };
    std::vector<Section> sections;
    for (size_t at = 1; at + 3 <= size;) {
        const bool blob = data[at] & 1;
        size_t length = data[at + 1] | size_t(data[at + 2]) << 8;
        at += 3;
        length = std::min(length, size - at);
        sections.push_back({blob, std::vector<uint8_t>(data + at, data + at + length)});
        at += length;
    }
    capture::Metadata meta;
    meta.program = "fuzz";
    meta.width = width;
    meta.height = height;
    capture::CaptureWriter writer;
    std::string error;
    if (!writer.open(gPath, meta, error)) {
        std::fprintf(stderr, "fuzz_replay: %s\n", error.c_str());
        std::abort();
    }
    // Blobs first: a frame may refer to any of them.
    std::vector<capture::BlobHash> hashes;
    for (const Section& s : sections) {
        if (s.blob) hashes.push_back(writer.putBlob(s.bytes.data(), s.bytes.size()));
    }
    uint64_t frame = 0;
    for (Section& s : sections) {
        if (s.blob) continue;
        resolveBlobTokens(s.bytes, hashes);
        writer.writeFrame(1, ++frame, s.bytes.data(), s.bytes.size());
    }
    return writer.close(error);
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
    unsetenv("NPRGL_RECORD"); // as `nprgl replay`: a replay never records itself
    unsetenv("NPRGL_EXPORT");
    unsetenv("NPRGL_SCREENSHOT");
    const char* dir = access("/dev/shm", W_OK) == 0 ? "/dev/shm" : "/tmp";
    gPath = std::string(dir) + "/nprgl-fuzz-replay-" + std::to_string(getpid()) + ".nprgl";
    std::atexit([] { unlink(gPath.c_str()); });
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    int width = 0, height = 0;
    if (!writeCapture(data, size, width, height)) return 0;
    ReplayOptions options;
    // Small limits: every input must run in bounded time and memory (the defaults are
    // sized for real programs).
    options.limits.drawVertices = 1 << 16;
    options.limits.listWork = 1 << 18;
    options.limits.names = 1 << 12;
    options.limits.texels = 1 << 18;
    options.limits.bufferBytes = 1 << 22;
    options.limits.totalBytes = 1 << 26;
    options.limits.totalWork = 1 << 22;
    std::string error;
    if (!Replayer::run(gPath, options, error) && error.empty()) __builtin_trap(); // say why
    if (error.find('\n') != std::string::npos) __builtin_trap();                  // one line
    if (gVerbose && !error.empty()) std::fprintf(stderr, "fuzz_replay: %s\n", error.c_str());
    return 0;
}
