#pragma once

#include <cstdint>
#include <cstring>
#include <functional>
#include <memory>

namespace nprgl {

// Encodes calls into one growing buffer per context and frame. The per-vertex path is a
// bounds check and a memcpy into memory kept from frame to frame: the buffer grows (rarely,
// by doubling) only until it holds the largest frame, then it is reused.
//
// Layout of a call: u16 opcode; for calls with arrays, strings or images a u32 payload
// length; then the arguments, little-endian, in declaration order. An array is a u32 byte
// count followed by the bytes; kNullArray marks a null pointer; kBlobArray is followed by
// a u64 hash and u64 size of a blob stored once in the capture file.
class CallWriter {
public:
    static constexpr uint32_t kNullArray = 0xFFFFFFFEu;
    static constexpr uint32_t kBlobArray = 0xFFFFFFFFu;
    static constexpr size_t kInlineLimit = 1024; // larger arrays become blobs

    // Stores a blob and returns its hash; set by the recorder to the capture file's.
    using BlobSink = std::function<uint64_t(const void*, size_t)>;

    CallWriter();
    ~CallWriter();
    CallWriter(const CallWriter&) = delete;
    CallWriter& operator=(const CallWriter&) = delete;

    void setBlobSink(BlobSink sink) { mBlobSink = std::move(sink); }
    void clear() { mSize = 0; }
    void truncate(size_t size) { mSize = size < mSize ? size : mSize; }
    const uint8_t* data() const { return mData.get(); }
    size_t size() const { return mSize; }

    template <typename T>
    __attribute__((always_inline)) void put(T value)
    {
        reserve(sizeof value);
        std::memcpy(mData.get() + mSize, &value, sizeof value);
        mSize += sizeof value;
    }
    void op(uint16_t opcode) { put(opcode); }

    // A call with a variable payload: beginPayload reserves its length, endPayload fills it.
    size_t beginPayload()
    {
        put<uint32_t>(0);
        return mSize;
    }
    void endPayload(size_t mark)
    {
        uint32_t length = static_cast<uint32_t>(mSize - mark);
        std::memcpy(mData.get() + mark - sizeof length, &length, sizeof length);
    }

    void putBytes(const void* bytes, size_t size);
    void putString(const char* text);
    void putSources(int count, const char* const* strings, const int* lengths);

private:
    __attribute__((always_inline)) void reserve(size_t n)
    {
        if (mSize + n > mCapacity) grow(n);
    }
    void grow(size_t n);

    std::unique_ptr<uint8_t[]> mData;
    size_t mSize = 0;
    size_t mCapacity = 0;
    BlobSink mBlobSink;
};

} // namespace nprgl
