#include "common/TextFile.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

namespace nprgl {

namespace {

std::string sizeText(size_t bytes)
{
    constexpr size_t kMiB = size_t(1) << 20;
    if (bytes >= kMiB && bytes % kMiB == 0) return std::to_string(bytes / kMiB) + " MiB";
    return std::to_string(bytes) + " bytes";
}

std::string overLimit(size_t size, size_t limit, const char* kind)
{
    return std::to_string(size) + " bytes, over the " + sizeText(limit) + " a " + kind +
           " may have; not read";
}

std::string notRegular(mode_t mode)
{
    return std::string("not a regular file (") + TextFile::typeName(mode) + ")";
}

} // namespace

const char* TextFile::typeName(mode_t mode)
{
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    if (S_ISREG(mode)) return "a regular file";
    return "a special file";
}

size_t TextFile::binaryAt(std::string_view text)
{
    for (size_t i = 0; i < text.size(); ++i) {
        const unsigned char c = static_cast<unsigned char>(text[i]);
        const bool control =
            c < 0x20 && c != '\t' && c != '\n' && c != '\v' && c != '\f' && c != '\r';
        if (control || c == 0x7f) return i;
    }
    return std::string_view::npos;
}

TextFile::Result TextFile::read(const std::string& path, const char* kind, std::string& text,
                                std::string& why, size_t limit)
{
    text.clear();
    why.clear();
    // Looked at before it is opened: opening a FIFO waits for a writer, a device may do
    // anything, and /dev/zero never ends.
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0) {
        if (errno == ENOENT) return Result::Missing;
        why = std::string("cannot read: ") + std::strerror(errno);
        return Result::Refused;
    }
    if (!S_ISREG(st.st_mode)) {
        why = notRegular(st.st_mode);
        return Result::Refused;
    }
    if (size_t(st.st_size) > limit) {
        why = overLimit(size_t(st.st_size), limit, kind);
        return Result::Refused;
    }
    // Non-blocking, and looked at again once open: it may have been replaced in between.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY | O_CLOEXEC);
    if (fd < 0) {
        if (errno == ENOENT) return Result::Missing;
        why = std::string("cannot read: ") + std::strerror(errno);
        return Result::Refused;
    }
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        why = notRegular(st.st_mode);
        ::close(fd);
        return Result::Refused;
    }
    // A file may say it is smaller than it reads (/proc) or grow: read one byte past the limit.
    text.resize(std::min(size_t(st.st_size), limit) + 1);
    size_t got = 0;
    while (got <= limit) {
        if (got == text.size()) text.resize(std::min(text.size() * 2, limit + 1));
        const ssize_t n = ::read(fd, text.data() + got, text.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            why = std::string("cannot read: ") + std::strerror(errno);
            ::close(fd);
            text.clear();
            return Result::Refused;
        }
        if (n == 0) break;
        got += size_t(n);
    }
    ::close(fd);
    if (got > limit) {
        why = "over the " + sizeText(limit) + " a " + kind + " may have; not read";
        text.clear();
        return Result::Refused;
    }
    text.resize(got);
    if (const size_t at = binaryAt(text); at != std::string::npos) {
        why = std::string("not a ") + kind + " (binary data at offset " + std::to_string(at) + ")";
        text.clear();
        return Result::Refused;
    }
    return Result::Read;
}

} // namespace nprgl
