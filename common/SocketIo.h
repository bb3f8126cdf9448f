// SocketIo: whole messages over a stream socket, as the live video's two sides send them.
#pragma once

#include <cstddef>
#include <string>

namespace nprgl {

class SocketIo {
public:
    // Sends all `bytes` (MSG_NOSIGNAL: a peer gone is false here, never a SIGPIPE for the
    // process); false on an error.
    static bool sendAll(int fd, const void* data, size_t bytes);
    // Reads exactly `bytes`; false at the end of the stream or on an error.
    static bool readAll(int fd, void* data, size_t bytes);
    // A stream socket (close-on-exec) listening on, or connected to, an abstract name (a
    // leading NUL: nothing in the file system to leave behind). -1 with errno on failure,
    // ENAMETOOLONG for a name the address cannot hold.
    static int listenAbstract(const std::string& name, int backlog);
    static int connectAbstract(const std::string& name);
};

} // namespace nprgl
