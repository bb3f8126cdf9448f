#pragma once

// TextFile: a small text file a user named (a configuration or preset file), read without ever
// blocking and never past a limit.

#include <sys/types.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace nprgl {

class TextFile {
public:
    enum class Result { Read, Missing, Refused };

    // What a configuration or preset file may weigh: a hand-written one is a few hundred bytes.
    static constexpr size_t kLimit = size_t(1) << 20;

    // Reads the regular file at `path` whole into `text`. Missing: nothing is there. Refused,
    // with `why` (to follow "PATH: "): not a regular file (a FIFO, a device, a directory: never
    // opened, so never waited on), over `limit` bytes (never read), unreadable (the reason the
    // system gave), or binary data, not text ("not a KIND (binary data at offset N)"). `kind`
    // names what the file was meant to be ("configuration file").
    static Result read(const std::string& path, const char* kind, std::string& text,
                       std::string& why, size_t limit = kLimit);
    // A file type in words, for a file that is not a regular one ("a FIFO").
    static const char* typeName(mode_t mode);
    // The offset of the first byte no text file holds (NUL, a control character other than
    // tab, line and page breaks, DEL), or npos.
    static size_t binaryAt(std::string_view text);
};

} // namespace nprgl
