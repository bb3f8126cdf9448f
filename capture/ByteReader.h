#pragma once

#include <cstdint>
#include <string>
#include <utility>

namespace nprgl::capture {

// Reads little-endian fields from a byte range that came from a file, never past its end.
// The first failure is remembered with the file offset where it happened, and every later
// read fails too, so a decoder can check once at the end.
class ByteReader {
public:
    // fileOffset: where data[0] lies in the file, for error messages.
    ByteReader(const uint8_t* data, size_t size, uint64_t fileOffset)
        : mData(data), mSize(size), mBase(fileOffset)
    {
    }

    bool ok() const { return mError.empty(); }
    const std::string& error() const { return mError; }
    uint64_t errorOffset() const { return mErrorOffset; }
    size_t position() const { return mPos; }
    size_t remaining() const { return mSize - mPos; }
    uint64_t fileOffset() const { return mBase + mPos; }

    uint32_t u32() { return uint32_t(get(4, "a 32-bit field")); }
    uint64_t u64() { return get(8, "a 64-bit field"); }

    // A u32 length (at most maxLength, and no more than the bytes that remain), then bytes.
    std::string string(uint32_t maxLength, const char* what)
    {
        uint64_t at = fileOffset();
        uint32_t length = u32();
        if (!ok()) return {};
        if (length > maxLength) {
            fail(at, std::string(what) + " length " + std::to_string(length) +
                         " is over the limit of " + std::to_string(maxLength) + " bytes");
            return {};
        }
        if (length > remaining()) {
            fail(at, std::string(what) + " length " + std::to_string(length) + " runs past " +
                         "the end of its chunk (" + std::to_string(remaining()) + " bytes left)");
            return {};
        }
        std::string s(reinterpret_cast<const char*>(mData + mPos), length);
        mPos += length;
        return s;
    }

    // Records a failure found by the caller (e.g. a count that cannot fit).
    void fail(uint64_t offset, std::string message)
    {
        if (!ok()) return;
        mErrorOffset = offset;
        mError = std::move(message);
        mPos = mSize;
    }

private:
    uint64_t get(int n, const char* what)
    {
        if (!ok()) return 0;
        if (remaining() < size_t(n)) {
            fail(fileOffset(), std::string("chunk ends inside ") + what);
            return 0;
        }
        uint64_t v = 0;
        for (int i = 0; i < n; ++i) v |= uint64_t(mData[mPos + i]) << (8 * i);
        mPos += n;
        return v;
    }

    const uint8_t* mData;
    size_t mSize;
    uint64_t mBase;
    size_t mPos = 0;
    std::string mError;
    uint64_t mErrorOffset = 0;
};

} // namespace nprgl::capture
