#pragma once

#include "stream/OpcodeMap.h"

#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace nprgl {

// Where a reader finds the blobs that calls refer to by hash (the capture file).
class BlobSource {
public:
    virtual ~BlobSource() = default;
    // Returns the blob's bytes (valid while the source lives) or null with a message.
    virtual const std::vector<uint8_t>* blob(uint64_t hash, std::string& error) = 0;
};

// Decodes the calls a CallWriter encoded. Every read is bounds-checked: malformed input sets
// an error (with the offset) and makes every later read return zero, so the generated
// decoders need one ok() check per call.
class CallReader {
public:
    // map: the capture's opcode numbering (null: this build's own).
    CallReader(const uint8_t* data, size_t size, BlobSource* blobs,
               const OpcodeMap* map = nullptr);

    bool atEnd() const { return mPos >= mSize; }
    bool ok() const { return mError.empty(); }
    const std::string& error() const { return mError; }
    size_t offset() const { return mPos; }
    void fail(const std::string& message);

    // The next call's opcode in this build's numbering; fails on a command it does not know.
    uint16_t opcode();

    template <typename T>
    T get()
    {
        T value{};
        if (mPos + sizeof value > mLimit) {
            fail("call truncated");
            return value;
        }
        std::memcpy(&value, mData + mPos, sizeof value);
        mPos += sizeof value;
        return value;
    }

    // An array of exactly `count` elements of T (or null). The pointer stays valid until the
    // next call is decoded.
    template <typename T>
    const T* getArray(size_t count)
    {
        size_t size = 0;
        const void* p = getBytes(size);
        if (p && size != count * sizeof(T)) {
            fail("array of " + std::to_string(size) + " bytes where " +
                 std::to_string(count * sizeof(T)) + " were expected");
            return nullptr;
        }
        return static_cast<const T*>(alignedCopy(p, size));
    }
    // Bytes of any length (images, index data), or null; size is set.
    const void* getBytes(size_t& size);
    // An image or index-data argument: null, bytes, or an offset into the bound pixel-unpack
    // or element buffer.
    const void* getImage();
    // How the last getImage argument was given, for a replayer to check it against the call.
    struct Image {
        enum Mode : uint8_t { kNull, kBytes, kOffset } mode = kNull;
        size_t size = 0;     // kBytes: the bytes given
        uint64_t offset = 0; // kOffset: into the bound buffer
    };
    const Image& lastImage() const { return mLastImage; }
    const char* getString();
    // Exactly `count` bytes (or null), returned with a zero after them.
    const char* getText(size_t count);
    // A batch reference (u64 hash, u64 size): the blob's bytes, or null with the error set.
    const std::vector<uint8_t>* getBlobRef();
    BlobSource* blobs() const { return mBlobs; }
    const OpcodeMap* opcodes() const { return mOpcodes; }

    struct Sources {
        const char* const* strings = nullptr;
        const int* lengths = nullptr;
        int count = 0;
    };
    Sources getSources(int count);

    // The kUncaptured pseudo-call's payload: the frame's calls that the recorder forwarded
    // without capturing them, by name and count.
    using Uncaptured = std::vector<std::pair<std::string, uint64_t>>;
    bool getUncaptured(Uncaptured& out);

    // Frames a call with a payload length: everything read must stay inside it, and
    // finish() checks that all of it was read.
    class Payload {
    public:
        explicit Payload(CallReader& r);
        bool finish();
        // Passes over what is left of it unread (a pseudo-call the reader has no use for).
        bool skip();

    private:
        CallReader& mReader;
        size_t mOuterLimit;
        size_t mEnd;
    };

private:
    const void* alignedCopy(const void* p, size_t size);

    const uint8_t* mData;
    size_t mSize;
    size_t mPos = 0;
    size_t mLimit;
    BlobSource* mBlobs;
    const OpcodeMap* mOpcodes;
    std::string mError;
    // Copies that outlive the pointer into mData (alignment) or hold strings.
    std::vector<std::vector<uint8_t>> mScratch;
    size_t mScratchUsed = 0;
    std::vector<const char*> mSourcePointers;
    std::vector<int> mSourceLengths;
    Image mLastImage;

    friend class Payload;
};

} // namespace nprgl
