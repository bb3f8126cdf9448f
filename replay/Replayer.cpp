#include "replay/Replayer.h"

#include "common/Log.h"
#include "common/PngImage.h"
#include "frame/Compositor.h"
#include "frame/ShadowArrays.h"
#include "replay/CaptureBlobs.h"
#include "replay/ReplaySink.h"
#include "shim/Api.h"
#include "shim/Context.h"
#include "shim/RealGl.h"
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

void drawProgress(size_t done, size_t total)
{
    const int width = 40;
    int filled = total ? int(width * done / total) : width;
    std::fprintf(stderr, "\r[%.*s%*s] %zu/%zu frames", filled,
                 "========================================", width - filled, "", done, total);
    if (done == total) std::fputc('\n', stderr);
}

} // namespace

uint32_t Replayer::defaultContext(const capture::CaptureReader& reader)
{
    std::map<uint32_t, size_t> perContext;
    for (const auto& f : reader.frames()) ++perContext[f.contextId];
    size_t best = 0;
    uint32_t contextId = 0;
    for (const auto& [id, n] : perContext) {
        if (n > best) best = n, contextId = id;
    }
    return contextId;
}

bool Replayer::run(const std::string& path, const ReplayOptions& options, std::string& error,
                   uint64_t* framesWritten)
{
    capture::CaptureReader reader;
    if (!reader.open(path, error)) return false;
    return run(reader, options, error, framesWritten, nullptr);
}

bool Replayer::run(const capture::CaptureReader& reader, const ReplayOptions& options,
                   std::string& error, uint64_t* framesWritten, capture::ReadReport* report)
{
    const std::string& path = reader.path();
    const auto& frames = reader.frames();
    Compositor::finishStyleWorkAtOnce();
    if (options.overlays) OverlayContrast::enable();
    const uint32_t contextId = options.contextId ? options.contextId : defaultContext(reader);
    const int width = options.width ? options.width : reader.metadata().width;
    const int height = options.height ? options.height : reader.metadata().height;
    if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
        error = path + ": no usable frame size (" + std::to_string(width) + "x" +
                std::to_string(height) + "); give --size WxH";
        return false;
    }

    // The context made current below is a Context of the pipeline: it takes this Config.
    if (options.config && !Config::use(*options.config)) {
        NPRGL_WARN("the replay's style comes too late (a context exists already): style %s",
                   Config::process().style.chainName().c_str());
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
    DrawCounts statsBefore;
    const ReplaySink* replaying = nullptr; // the sink below, for what the frame cleared to
    auto frameEnd = [&](uint64_t frame) {
        // The program's frame is complete; OSMesa renders into our buffer.
        // Through the context's own glFinish: the compositor draws what it holds, as at the
        // end of a live frame; and a swap's: what the next frame does not draw over is its
        // background.
        if (tThread.context) tThread.context->swapAtNextFrameEnd();
        tThread.dispatch->glFinish();
        if (options.stats) {
            // The run's counts since the last recorded frame: a program's own glFinish also
            // ends a frame on OSMesa, so a recorded frame may be several of the context's.
            const Compositor* c = tThread.context ? tThread.context->compositor() : nullptr;
            std::printf("frame %llu: 3D polygon draws: %s\n",
                        static_cast<unsigned long long>(frame),
                        c ? c->runCounts().since(statsBefore).describe().c_str()
                          : "not styled (style none)");
            if (c) statsBefore = c->runCounts();
            if (c && c->textureCounts().any()) {
                // The run's textures as they stand: each is counted once, at first sight.
                std::printf("frame %llu: textures as drawings: %s\n",
                            static_cast<unsigned long long>(frame),
                            c->textureCounts().describe().c_str());
            }
            if (OverlayContrast::measuring()) {
                Compositor* o = tThread.context ? tThread.context->compositor() : nullptr;
                std::printf("frame %llu: 2D draws: %s\n", static_cast<unsigned long long>(frame),
                            o ? OverlayLegibility::describe(o->takeOverlays()).c_str()
                              : "not measured (no compositor)");
            }
            uint8_t clear[3];
            if (replaying && replaying->frameClear(clear)) {
                std::printf("frame %llu: background: cleared to %u %u %u\n",
                            static_cast<unsigned long long>(frame), clear[0], clear[1],
                            clear[2]);
            } else {
                std::printf("frame %llu: background: no clear of the whole window\n",
                            static_cast<unsigned long long>(frame));
            }
        }
        if ((options.outDir.empty() && !options.onFrame) ||
            (!options.frames.empty() && !options.frames.contains(frame))) {
            return true;
        }
        PngImage image;
        image.width = width;
        image.height = height;
        image.rgba = buffer; // OSMesa's buffer: bottom row first
        image.flipRows();
        image.makeOpaque();
        if (options.onFrame && !options.onFrame(image, frameError)) return false;
        if (options.outDir.empty()) return true;
        char name[64];
        std::snprintf(name, sizeof name, "/frame_%010llu.png",
                      static_cast<unsigned long long>(frame));
        if (!image.write(options.outDir + name, frameError)) return false;
        ++written;
        return true;
    };
    ReplaySink sink(arrays, options.limits, frameEnd);
    sink.setWindowSize(width, height);
    replaying = &sink;
    const int recordedWidth = reader.metadata().width, recordedHeight = reader.metadata().height;
    if (recordedWidth > 0 && recordedHeight > 0 &&
        (width != recordedWidth || height != recordedHeight)) {
        // The program's picture resized, not cropped: it draws for the recorded window.
        sink.setWindowScale(double(width) / recordedWidth, double(height) / recordedHeight);
        NPRGL_INFO("replaying the %dx%d recording at %dx%d (the program's viewport and scissor "
                   "scaled)",
                   recordedWidth, recordedHeight, width, height);
    }
    CaptureBlobs blobs(reader);
    const OpcodeMap opcodes(reader.metadata().opcodeNames);
    std::vector<uint8_t> calls;
    bool ok = true;
    for (size_t i = 0; ok && i < frames.size(); ++i) {
        if (frames[i].contextId != contextId) continue;
        if (!options.frames.empty() && frames[i].frameNumber > options.frames.last()) break;
        // A read-back per 2D draw: only in the frames asked for.
        OverlayContrast::setPaused(!options.frames.empty() &&
                                   !options.frames.contains(frames[i].frameNumber));
        if (!reader.readFrame(i, calls, error)) {
            if (report) {
                NPRGL_ERROR("%s; frame %llu skipped", error.c_str(),
                            static_cast<unsigned long long>(frames[i].frameNumber));
                report->frameLost(i);
                error.clear();
                if (options.progress) drawProgress(++done, total);
                continue;
            }
            ok = false;
            break;
        }
        CallReader r(calls.data(), calls.size(), &blobs, &opcodes);
        for (uint64_t call = 0; ok && !r.atEnd(); ++call) {
            uint16_t opcode = r.opcode();
            const bool haveOpcode = r.ok();
            if (!haveOpcode || !decodeCall(r, opcode, sink)) {
                std::string why = !frameError.empty()  ? frameError
                                  : !sink.error().empty() ? sink.error()
                                  : !r.ok()               ? r.error()
                                                          : "unknown opcode " +
                                                            std::to_string(opcode);
                const char* name = haveOpcode ? opcodeName(opcode) : nullptr;
                // The n-th call of the frame (from 0), and where its chunk is in the file.
                error = path + ": frame " + std::to_string(frames[i].frameNumber) + ", call " +
                        std::to_string(call) + (name ? std::string(" (") + name + ")" : "") +
                        ", chunk at " + std::to_string(frames[i].offset) + ": " + why;
                ok = false;
            }
        }
        ++done;
        if (options.progress) drawProgress(done, total);
    }
    OSMesaMakeCurrent(nullptr, nullptr, GL_UNSIGNED_BYTE, 0, 0);
    OSMesaDestroyContext(ctx);
    // What the program did that the capture lacks: the replayed frames may differ there.
    for (const auto& [name, seen] : sink.uncaptured()) {
        NPRGL_WARN("context %u: the capture lacks %llu call%s to %s (not captured), in "
                   "frame%s %s", contextId, static_cast<unsigned long long>(seen.calls),
                   seen.calls == 1 ? "" : "s", name.c_str(), seen.frames.size() == 1 ? "" : "s",
                   FrameSet::describe(seen.frames).c_str());
    }
    if (framesWritten) *framesWritten = written;
    return ok;
}

} // namespace nprgl
