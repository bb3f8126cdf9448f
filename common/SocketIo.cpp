#include "common/SocketIo.h"

#include <cerrno>
#include <cstdint>
#include <sys/socket.h>

namespace nprgl {

bool SocketIo::sendAll(int fd, const void* data, size_t bytes)
{
    const auto* at = static_cast<const uint8_t*>(data);
    while (bytes > 0) {
        const ssize_t sent = send(fd, at, bytes, MSG_NOSIGNAL);
        if (sent < 0 && errno == EINTR) continue;
        if (sent <= 0) return false;
        at += sent;
        bytes -= size_t(sent);
    }
    return true;
}

bool SocketIo::readAll(int fd, void* data, size_t bytes)
{
    auto* at = static_cast<uint8_t*>(data);
    while (bytes > 0) {
        const ssize_t got = recv(fd, at, bytes, MSG_WAITALL);
        if (got < 0 && errno == EINTR) continue;
        if (got <= 0) return false;
        at += got;
        bytes -= size_t(got);
    }
    return true;
}

} // namespace nprgl
