#include "stream/CallWriter.h"

#include <algorithm>

namespace nprgl {

CallWriter::CallWriter() : mData(new uint8_t[1 << 20]), mCapacity(1 << 20) {}

CallWriter::~CallWriter() = default;

void CallWriter::grow(size_t n)
{
    size_t capacity = std::max(mCapacity * 2, mSize + n);
    std::unique_ptr<uint8_t[]> bigger(new uint8_t[capacity]);
    std::memcpy(bigger.get(), mData.get(), mSize);
    mData = std::move(bigger);
    mCapacity = capacity;
}

void CallWriter::putBytes(const void* bytes, size_t size)
{
    if (!bytes) {
        put<uint32_t>(kNullArray);
        return;
    }
    if (size >= kInlineLimit && mBlobSink) {
        put<uint32_t>(kBlobArray);
        put<uint64_t>(mBlobSink(bytes, size));
        put<uint64_t>(size);
        return;
    }
    // Inline arrays are below kInlineLimit, or the sink is missing (then size fits u32 for
    // any real GL call: larger ones are blobs).
    put<uint32_t>(static_cast<uint32_t>(size));
    reserve(size);
    std::memcpy(mData.get() + mSize, bytes, size);
    mSize += size;
}

void CallWriter::putString(const char* text)
{
    putBytes(text, text ? std::strlen(text) + 1 : 0);
}

void CallWriter::putSources(int count, const char* const* strings, const int* lengths)
{
    put<int32_t>(count);
    for (int i = 0; i < count; ++i) {
        const char* s = strings ? strings[i] : nullptr;
        size_t n = !s ? 0 : (lengths && lengths[i] >= 0) ? size_t(lengths[i]) : std::strlen(s);
        put<uint32_t>(static_cast<uint32_t>(n));
        reserve(n);
        if (n) std::memcpy(mData.get() + mSize, s, n);
        mSize += n;
    }
}

} // namespace nprgl
