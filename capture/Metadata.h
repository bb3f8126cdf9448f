#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace nprgl::capture {

// What a capture file says about the program that was recorded.
struct Metadata {
    std::string program; // e.g. "glxgears"
    std::vector<std::string> commandLine;
    std::string glVendor, glRenderer, glVersion;
    int width = 0, height = 0; // drawable size when the first frame was shown
    uint32_t pid = 0;
    uint64_t startTimeUnix = 0;
    std::vector<std::pair<std::string, std::string>> extra; // free-form key/values
    // The GL command behind each opcode of the file's Stream, in opcode order (version 2 on),
    // so a reader built from another gl.xml can map the file's numbers onto its own. Empty in
    // version-1 files, whose numbering every later reader keeps as its own first opcodes.
    std::vector<std::string> opcodeNames;

    bool operator==(const Metadata&) const = default;
};

// XXH3_64bits of the blob bytes.
using BlobHash = uint64_t;

BlobHash hashBlob(const void* data, size_t size);

} // namespace nprgl::capture
