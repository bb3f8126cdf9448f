// SocketIo: whole messages over a stream socket, as the live video's two sides send them.
#pragma once

#include <cstddef>

namespace nprgl {

class SocketIo {
public:
    // Sends all `bytes` (MSG_NOSIGNAL: a peer gone is false here, never a SIGPIPE for the
    // process); false on an error.
    static bool sendAll(int fd, const void* data, size_t bytes);
    // Reads exactly `bytes`; false at the end of the stream or on an error.
    static bool readAll(int fd, void* data, size_t bytes);
};

} // namespace nprgl
