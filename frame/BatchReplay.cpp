#include "frame/BatchReplay.h"

#include "shim/RealGl.h"
#include "stream/CallDecoder.h"
#include "stream/Opcodes.h"

#include <vector>

namespace nprgl {

namespace {

// The decodeCall sink: every call to the driver as it was made. A batch holds no pointer
// calls or queries, so no client pointer or scratch memory is ever needed.
class DriverSink {
public:
    static constexpr bool kReplays = true;

    const GlDispatch& gl() const { return gRealGl; }
    bool before(uint16_t) { return true; }
    void after(uint16_t) {}
    template <typename T>
    T* scratch(size_t n)
    {
        mScratch.assign((n + 1) * sizeof(T), 0);
        return reinterpret_cast<T*>(mScratch.data());
    }
    const void* clientPointer(uint64_t, int) { return nullptr; }
    bool pseudo(CallReader& r, uint16_t opcode)
    {
        // The array data glArrayElement read is the program's own, still in its arrays.
        if (opcode == op::kArrayData) return CallReader::Payload(r).skip();
        if (opcode == op::kUncaptured) {
            CallReader::Uncaptured ignored;
            return r.getUncaptured(ignored);
        }
        r.fail("unexpected pseudo-call in a batch");
        return false;
    }

private:
    std::vector<uint8_t> mScratch;
};

} // namespace

bool replayBatch(const uint8_t* data, size_t size)
{
    CallReader r(data, size, nullptr);
    DriverSink sink;
    while (!r.atEnd()) {
        const uint16_t opcode = r.opcode();
        if (!r.ok()) return false;
        if (opcode == op::glEnd) return true;
        if (!decodeCall(r, opcode, sink)) return false;
    }
    return true;
}

} // namespace nprgl
