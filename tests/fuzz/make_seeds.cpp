// Writes the fuzzer's seed corpus: small capture files of each shape the writer makes (whole,
// cut off by a killed program, stored frames, empty) and the unclosed shapes the reader scans
// (a killed program's file, one cut inside its last chunk, one with a damaged chunk in the
// middle). Generated, so no binary is committed.
// Usage: make_seeds DIR

#include "capture/CaptureWriter.h"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace nprgl::capture;

namespace {

std::vector<uint8_t> bytes(uint32_t seed, size_t size, bool compressible)
{
    std::vector<uint8_t> out(size);
    uint32_t x = seed * 2654435761u + 1;
    for (size_t i = 0; i < size; ++i) {
        x = x * 1103515245u + 12345u;
        out[i] = compressible ? uint8_t(i % 5) : uint8_t(x >> 24);
    }
    return out;
}

bool copyFile(const std::string& from, const std::string& to)
{
    std::ifstream in(from, std::ios::binary);
    std::vector<char> data((std::istreambuf_iterator<char>(in)), {});
    std::ofstream out(to, std::ios::binary | std::ios::trunc);
    out.write(data.data(), std::streamsize(data.size()));
    return bool(out);
}

bool writeSeed(const std::string& path, int frames, bool compressible, bool close,
               const std::string& copyBeforeClose)
{
    Metadata meta;
    if (frames > 0) {
        meta.program = "glxgears";
        meta.commandLine = {"glxgears", "-info"};
        meta.glVendor = "Mesa";
        meta.glRenderer = "llvmpipe";
        meta.glVersion = "4.5";
        meta.width = 300;
        meta.height = 300;
        meta.pid = 1234;
        meta.startTimeUnix = 1700000000;
        meta.extra = {{"style", "toon"}};
    }
    CaptureWriter writer;
    std::string error;
    if (!writer.open(path, meta, error)) {
        std::fprintf(stderr, "make_seeds: %s\n", error.c_str());
        return false;
    }
    for (int i = 0; i < frames; ++i) {
        std::vector<uint8_t> blob = bytes(100 + i, 40, compressible);
        writer.putBlob(blob.data(), blob.size());
        std::vector<uint8_t> calls = bytes(i, 60 + 10 * i, compressible);
        if (!writer.writeFrame(1 + i % 2, 1 + i / 2, calls.data(), calls.size())) return false;
        if (i == 1) writer.writeCallCounts({{"glFogCoordf", 3}, {"glWindowPos2i", 1}});
    }
    if (!copyBeforeClose.empty() && !copyFile(path, copyBeforeClose)) return false;
    if (close && !writer.close(error)) {
        std::fprintf(stderr, "make_seeds: %s\n", error.c_str());
        return false;
    }
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    if (argc != 2) {
        std::fprintf(stderr, "usage: make_seeds DIR\n");
        return 2;
    }
    std::string dir = argv[1];
    bool ok = writeSeed(dir + "/closed.nprgl", 4, true, true, dir + "/killed.nprgl") &&
              writeSeed(dir + "/stored.nprgl", 2, false, true, "") &&
              writeSeed(dir + "/empty.nprgl", 0, true, true, "") &&
              writeSeed(dir + "/long.nprgl", 9, true, true, dir + "/killed-long.nprgl");
    if (!ok) return 1;
    // Unclosed files as the reader meets them: cut inside the last chunk, and one with a
    // damaged chunk between whole ones (the scan skips it and goes on).
    std::ifstream in(dir + "/killed-long.nprgl", std::ios::binary);
    std::vector<char> killed((std::istreambuf_iterator<char>(in)), {});
    if (killed.size() < 200) return 1;
    std::ofstream(dir + "/killed-cut.nprgl", std::ios::binary)
        .write(killed.data(), std::streamsize(killed.size() - 7));
    killed[killed.size() / 2] ^= 0x20;
    std::ofstream(dir + "/killed-damaged.nprgl", std::ios::binary)
        .write(killed.data(), std::streamsize(killed.size()));
    return 0;
}
