#include "shim/Replayer.h"

#include "common/Log.h"
#include "common/PngImage.h"
#include "shim/Api.h"
#include "shim/CaptureBlobs.h"
#include "shim/ClientArrays.h"
#include "shim/RealGl.h"
#include "shim/ShadowArrays.h"
#include "shim/ThreadState.h"
#include "stream/CallDecoder.h"
#include "stream/Opcodes.h"

#include <cstdio>
#include <map>
#include <memory>
#include <unistd.h>
#include <vector>

namespace nprgl {

namespace {

constexpr size_t kMaxScratch = size_t(1) << 24;

// The replaying sink of decodeCall.
class ReplaySink {
public:
    static constexpr bool kReplays = true;

    ReplaySink(ShadowArrays& arrays, std::function<bool(uint64_t)> frameEnd)
        : mArrays(arrays), mFrameEnd(std::move(frameEnd))
    {
    }

    const GlDispatch& gl() const { return *tThread.dispatch; }
    bool before(uint16_t opcode)
    {
        mOpcode = opcode;
        if (mScratchTooBig) {
            mError = "count too large for a generated name list";
            return false;
        }
        return true;
    }
    void after(uint16_t opcode)
    {
        // The arrays and the buffers that decide where a pointer points.
        if (opcode == op::glClientActiveTexture) {
            GLint unit = GL_TEXTURE0;
            gRealGl.glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &unit);
            mClientActiveTexture = unit - GL_TEXTURE0;
        }
    }
    template <typename T>
    T* scratch(size_t n)
    {
        mScratchTooBig = n > kMaxScratch;
        mScratch.assign(std::min(n, kMaxScratch) * sizeof(T) + sizeof(T), 0);
        return reinterpret_cast<T*>(mScratch.data());
    }
    // A recorded client-array pointer: an offset when a buffer is bound, else our shadow.
    const void* clientPointer(uint64_t value, int attribIndex)
    {
        GLint buffer = 0;
        gRealGl.glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &buffer);
        if (buffer) return reinterpret_cast<const void*>(uintptr_t(value));
        int slot = attribIndex >= 0 ? (attribIndex < 16 ? kAttribArray0 + attribIndex : -1)
                                    : slotForPointerOp(mOpcode);
        return slot >= 0 ? mArrays.base(slot) : nullptr;
    }
    bool pseudo(CallReader& r, uint16_t opcode)
    {
        if (opcode == op::kFrameEnd) {
            uint64_t frame = r.get<uint64_t>();
            return r.ok() && mFrameEnd(frame);
        }
        if (opcode == op::kArrayData) return mArrays.apply(r);
        if (opcode == op::kBatchRef) return expandBatchRef(r, *this, mDepth);
        r.fail("unknown opcode " + std::to_string(opcode));
        return false;
    }
    const std::string& error() const { return mError; }

private:
    int slotForPointerOp(uint16_t opcode) const
    {
        switch (opcode) {
        case op::glVertexPointer: return kVertexArray;
        case op::glNormalPointer: return kNormalArray;
        case op::glColorPointer: return kColorArray;
        case op::glSecondaryColorPointer: return kSecondaryColorArray;
        case op::glFogCoordPointer: return kFogCoordArray;
        case op::glIndexPointer: return kIndexArray;
        case op::glEdgeFlagPointer: return kEdgeFlagArray;
        case op::glTexCoordPointer:
            return mClientActiveTexture >= 0 && mClientActiveTexture < 8
                       ? kTexCoordArray0 + mClientActiveTexture
                       : -1;
        default: return -1;
        }
    }

    ShadowArrays& mArrays;
    std::function<bool(uint64_t)> mFrameEnd;
    uint16_t mOpcode = 0;
    int mClientActiveTexture = 0;
    std::vector<uint8_t> mScratch;
    bool mScratchTooBig = false;
    int mDepth = 0;
    std::string mError;
};

void drawProgress(size_t done, size_t total)
{
    const int width = 40;
    int filled = total ? int(width * done / total) : width;
    std::fprintf(stderr, "\r[%.*s%*s] %zu/%zu frames", filled,
                 "========================================", width - filled, "", done, total);
    if (done == total) std::fputc('\n', stderr);
}

} // namespace

bool Replayer::run(const std::string& path, const ReplayOptions& options, std::string& error,
                   uint64_t* framesWritten)
{
    capture::CaptureReader reader;
    if (!reader.open(path, error)) return false;
    const auto& frames = reader.frames();
    uint32_t contextId = options.contextId;
    if (!contextId) {
        std::map<uint32_t, size_t> perContext;
        for (const auto& f : frames) ++perContext[f.contextId];
        size_t best = 0;
        for (const auto& [id, n] : perContext) {
            if (n > best) best = n, contextId = id;
        }
    }
    const int width = options.width ? options.width : reader.metadata().width;
    const int height = options.height ? options.height : reader.metadata().height;
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
        error = path + ": no usable frame size (" + std::to_string(width) + "x" +
                std::to_string(height) + "); give --size WxH";
        return false;
    }

    OSMesaContext ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 8, 0, nullptr);
    if (!ctx) {
        error = "cannot create an OSMesa context";
        return false;
    }
    std::vector<uint8_t> buffer(size_t(width) * height * 4);
    if (!OSMesaMakeCurrent(ctx, buffer.data(), GL_UNSIGNED_BYTE, width, height)) {
        OSMesaDestroyContext(ctx);
        error = "cannot make the OSMesa context current";
        return false;
    }

    size_t total = 0;
    for (const auto& f : frames) total += f.contextId == contextId;
    uint64_t written = 0;
    size_t done = 0;
    ShadowArrays arrays;
    std::string frameError;
    auto frameEnd = [&](uint64_t frame) {
        // The program's frame is complete; OSMesa renders into our buffer.
        // Through the context's own glFinish: the compositor draws what it holds, as at the
        // end of a live frame.
        tThread.dispatch->glFinish();
        if (options.outDir.empty() ||
            (!options.frames.empty() && !options.frames.contains(frame))) {
            return true;
        }
        PngImage image;
        image.width = width;
        image.height = height;
        image.rgba = buffer; // OSMesa's buffer: bottom row first
        image.flipRows();
        char name[64];
        std::snprintf(name, sizeof name, "/frame_%010llu.png",
                      static_cast<unsigned long long>(frame));
        if (!image.write(options.outDir + name, frameError)) return false;
        ++written;
        return true;
    };
    ReplaySink sink(arrays, frameEnd);
    CaptureBlobs blobs(reader);
    std::vector<uint8_t> calls;
    bool ok = true;
    for (size_t i = 0; ok && i < frames.size(); ++i) {
        if (frames[i].contextId != contextId) continue;
        if (!options.frames.empty() && frames[i].frameNumber > options.frames.last()) break;
        if (!reader.readFrame(i, calls, error)) {
            ok = false;
            break;
        }
        CallReader r(calls.data(), calls.size(), &blobs);
        while (ok && !r.atEnd()) {
            uint16_t opcode = r.get<uint16_t>();
            if (!r.ok() || !decodeCall(r, opcode, sink)) {
                std::string why = !frameError.empty()  ? frameError
                                  : !sink.error().empty() ? sink.error()
                                  : !r.ok()               ? r.error()
                                                          : "unknown opcode " +
                                                            std::to_string(opcode);
                error = path + ": frame " + std::to_string(frames[i].frameNumber) + " at " +
                        std::to_string(frames[i].offset) + ": " + why;
                ok = false;
            }
        }
        ++done;
        if (options.progress) drawProgress(done, total);
    }
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(ctx);
    if (framesWritten) *framesWritten = written;
    return ok;
}

} // namespace nprgl
