#pragma once

#include <cstdint>
#include <cstring>
#include <string_view>
#include <vector>

namespace nprgl::capture {

// Appends little-endian fields to a byte buffer (the capture format's only byte order).
class ByteWriter {
public:
    explicit ByteWriter(std::vector<uint8_t>& out) : mOut(out) {}

    void u32(uint32_t v) { put(v, 4); }
    void u64(uint64_t v) { put(v, 8); }
    void bytes(const void* data, size_t size)
    {
        if (size == 0) return;
        size_t at = mOut.size();
        mOut.resize(at + size);
        std::memcpy(mOut.data() + at, data, size);
    }
    // A u32 length, then the bytes (no terminator).
    void string(std::string_view s)
    {
        u32(uint32_t(s.size()));
        bytes(s.data(), s.size());
    }

private:
    void put(uint64_t v, int n)
    {
        for (int i = 0; i < n; ++i) mOut.push_back(uint8_t(v >> (8 * i)));
    }

    std::vector<uint8_t>& mOut;
};

} // namespace nprgl::capture
