#include "common/SocketIo.h"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

namespace nprgl {

namespace {

// A socket with `name`'s abstract address given to `join` (bind or connect); -1 with errno.
template <typename Join>
int abstractSocket(const std::string& name, Join join)
{
    sockaddr_un address {};
    address.sun_family = AF_UNIX;
    if (name.size() + 1 > sizeof address.sun_path) {
        errno = ENAMETOOLONG;
        return -1;
    }
    std::memcpy(address.sun_path + 1, name.data(), name.size());
    const socklen_t length = socklen_t(offsetof(sockaddr_un, sun_path) + 1 + name.size());
    const int fd = socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) return -1;
    if (!join(fd, reinterpret_cast<const sockaddr*>(&address), length)) {
        const int error = errno;
        close(fd);
        errno = error;
        return -1;
    }
    return fd;
}

} // namespace

int SocketIo::listenAbstract(const std::string& name, int backlog)
{
    return abstractSocket(name, [backlog](int fd, const sockaddr* address, socklen_t length) {
        return bind(fd, address, length) == 0 && listen(fd, backlog) == 0;
    });
}

int SocketIo::connectAbstract(const std::string& name)
{
    return abstractSocket(name, [](int fd, const sockaddr* address, socklen_t length) {
        return connect(fd, address, length) == 0;
    });
}

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
