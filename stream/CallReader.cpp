#include "stream/CallReader.h"

#include "stream/CallWriter.h"

namespace nprgl {

CallReader::CallReader(const uint8_t* data, size_t size, BlobSource* blobs,
                       const OpcodeMap* map)
    : mData(data), mSize(size), mLimit(size), mBlobs(blobs), mOpcodes(map)
{
}

uint16_t CallReader::opcode()
{
    const uint16_t raw = get<uint16_t>();
    if (!ok() || !mOpcodes) return raw;
    const uint16_t mine = mOpcodes->translate(raw);
    if (mine == OpcodeMap::kUnknown) fail(mOpcodes->unknown(raw));
    return mine;
}

void CallReader::fail(const std::string& message)
{
    if (mError.empty()) mError = "offset " + std::to_string(mPos) + ": " + message;
    mPos = mLimit = mSize; // every later read fails
}

const void* CallReader::getBytes(size_t& size)
{
    size = 0;
    uint32_t length = get<uint32_t>();
    if (!ok() || length == CallWriter::kNullArray) return nullptr;
    if (length == CallWriter::kBlobArray) {
        uint64_t hash = get<uint64_t>();
        uint64_t blobSize = get<uint64_t>();
        if (!ok()) return nullptr;
        std::string error;
        const std::vector<uint8_t>* blob = mBlobs ? mBlobs->blob(hash, error) : nullptr;
        if (!blob) {
            fail(mBlobs ? error : "blob reference without a capture file");
            return nullptr;
        }
        if (blob->size() != blobSize) {
            fail("blob size mismatch");
            return nullptr;
        }
        size = blob->size();
        return blob->data();
    }
    if (length > mLimit - mPos) {
        fail("array of " + std::to_string(length) + " bytes runs past the call");
        return nullptr;
    }
    const void* p = mData + mPos;
    mPos += length;
    size = length;
    return p;
}

const std::vector<uint8_t>* CallReader::getBlobRef()
{
    uint64_t hash = get<uint64_t>();
    uint64_t size = get<uint64_t>();
    if (!ok()) return nullptr;
    std::string error;
    const std::vector<uint8_t>* blob = mBlobs ? mBlobs->blob(hash, error) : nullptr;
    if (!blob || blob->size() != size) {
        fail(blob     ? "blob size mismatch"
             : mBlobs ? error
                      : "blob reference without a capture file");
        return nullptr;
    }
    return blob;
}

const void* CallReader::alignedCopy(const void* p, size_t size)
{
    if (!p || reinterpret_cast<uintptr_t>(p) % alignof(double) == 0) return p;
    if (mScratchUsed == mScratch.size()) mScratch.emplace_back();
    std::vector<uint8_t>& copy = mScratch[mScratchUsed++];
    copy.assign(static_cast<const uint8_t*>(p), static_cast<const uint8_t*>(p) + size);
    // vector storage comes from operator new, aligned for any fundamental type.
    return copy.data();
}

const void* CallReader::getImage()
{
    mLastImage = Image{};
    uint8_t mode = get<uint8_t>();
    if (mode == 2) {
        mLastImage.mode = Image::kOffset;
        mLastImage.offset = get<uint64_t>();
        return reinterpret_cast<const void*>(uintptr_t(mLastImage.offset));
    }
    if (mode != 1 && mode != 0) fail("bad image mode");
    if (mode != 1) return nullptr;
    size_t size = 0;
    const void* bytes = getBytes(size); // before size is read: argument order is unspecified
    if (bytes) mLastImage = Image{Image::kBytes, size, 0};
    return alignedCopy(bytes, size);
}

const char* CallReader::getText(size_t count)
{
    size_t size = 0;
    const void* p = getBytes(size);
    if (!p) return nullptr;
    if (size != count) {
        fail("text of " + std::to_string(size) + " bytes where " + std::to_string(count) +
             " were expected");
        return nullptr;
    }
    if (mScratchUsed == mScratch.size()) mScratch.emplace_back();
    std::vector<uint8_t>& copy = mScratch[mScratchUsed++];
    copy.assign(static_cast<const uint8_t*>(p), static_cast<const uint8_t*>(p) + size);
    copy.push_back(0);
    return reinterpret_cast<const char*>(copy.data());
}

const char* CallReader::getString()
{
    size_t size = 0;
    const char* s = static_cast<const char*>(getBytes(size));
    if (s && (size == 0 || s[size - 1] != '\0')) {
        fail("string without terminator");
        return nullptr;
    }
    return s;
}

bool CallReader::getUncaptured(Uncaptured& out)
{
    out.clear();
    Payload payload(*this);
    const uint32_t n = get<uint32_t>();
    // Each entry takes at least a length, a terminator and a count.
    if (ok() && n > (mLimit - mPos) / 13) fail("uncaptured-call count " + std::to_string(n));
    for (uint32_t i = 0; i < n && ok(); ++i) {
        const char* name = getString();
        const uint64_t count = get<uint64_t>();
        if (ok()) out.emplace_back(name, count);
    }
    return payload.finish();
}

CallReader::Sources CallReader::getSources(int count)
{
    Sources sources;
    int32_t stored = get<int32_t>();
    if (!ok() || stored != count || count < 0 || size_t(count) > (mLimit - mPos) / 4) {
        if (ok()) fail("bad shader source count");
        return sources;
    }
    mSourcePointers.assign(size_t(count), nullptr);
    mSourceLengths.assign(size_t(count), 0);
    for (int i = 0; i < count; ++i) {
        uint32_t n = get<uint32_t>();
        if (!ok() || n > mLimit - mPos) {
            fail("shader source runs past the call");
            return sources;
        }
        mSourcePointers[i] = reinterpret_cast<const char*>(mData + mPos);
        mSourceLengths[i] = static_cast<int>(n);
        mPos += n;
    }
    sources.strings = mSourcePointers.data();
    sources.lengths = mSourceLengths.data();
    sources.count = count;
    return sources;
}

CallReader::Payload::Payload(CallReader& r) : mReader(r), mOuterLimit(r.mLimit), mEnd(r.mLimit)
{
    uint32_t length = r.get<uint32_t>();
    if (!r.ok()) return;
    if (length > r.mLimit - r.mPos) {
        r.fail("call payload of " + std::to_string(length) + " bytes runs past the frame");
        return;
    }
    mEnd = r.mPos + length;
    r.mLimit = mEnd;
    r.mScratchUsed = 0;
}

bool CallReader::Payload::finish()
{
    if (!mReader.ok()) return false;
    if (mReader.mPos != mEnd) {
        mReader.fail("call payload not fully used");
        return false;
    }
    mReader.mLimit = mOuterLimit;
    return true;
}

bool CallReader::Payload::skip()
{
    if (!mReader.ok()) return false;
    mReader.mPos = mEnd;
    return finish();
}

} // namespace nprgl
