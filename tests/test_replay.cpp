// The replayer against hostile call streams: calls a driver would trust and crash or hang on
// (draws past their arrays, offsets without buffers, short images, lists that call lists)
// are refused with one line naming the frame and the call, in-process and by `nprgl replay`.

#include "capture/CaptureWriter.h"
#include "replay/Replayer.h"
#include "stream/CallWriter.h"
#include "stream/GlSizes.h"
#include "stream/Opcodes.h"
#include "tests/support/Process.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

using namespace nprgl;
using namespace nprgl::test;

namespace {

// Plain replays: the shim reads its settings once, at the first context.
const bool kStyleNone = setenv("NPRGL_STYLE", "none", 1) == 0;

const float kTriangle[] = {-1, -1, 0, 1, -1, 0, 0, 1, 0};

template <typename... A> void call(CallWriter& w, uint16_t opcode, A... args)
{
    w.op(opcode);
    (w.put(args), ...);
}

// Calls with a pointer, array or image argument carry a payload length.
template <typename... A> size_t beginCall(CallWriter& w, uint16_t opcode, A... args)
{
    w.op(opcode);
    size_t mark = w.beginPayload();
    (w.put(args), ...);
    return mark;
}

void arrayData(CallWriter& w, uint8_t slot, const void* data, size_t size)
{
    size_t mark = beginCall(w, op::kArrayData, slot, uint64_t(0));
    w.putBytes(data, size);
    w.endPayload(mark);
}

// A vertex array of one triangle from the shadow arrays: 3 calls.
void triangleArray(CallWriter& w)
{
    call(w, op::glEnableClientState, GLenum(GL_VERTEX_ARRAY));
    w.endPayload(beginCall(w, op::glVertexPointer, GLint(3), GLenum(GL_FLOAT), GLsizei(0),
                           uint64_t(0x1000)));
    arrayData(w, 0, kTriangle, sizeof kTriangle);
}

using Frame = std::function<void(CallWriter&)>;

// A capture of these blobs and frames (context 1, frames 1, 2, ...), each frame closed by
// a FrameEnd.
std::string writeCapture(const std::string& name, const std::vector<Frame>& frames,
                         const std::vector<std::vector<uint8_t>>& blobs = {})
{
    const std::string path = freshDir("replay_" + name) + "/" + name + ".nprgl";
    capture::Metadata meta;
    meta.program = "test_replay";
    meta.width = 32;
    meta.height = 32;
    capture::CaptureWriter writer;
    std::string error;
    EXPECT_TRUE(writer.open(path, meta, error)) << error;
    for (const auto& blob : blobs)
        writer.putBlob(blob.data(), blob.size());
    uint64_t number = 0;
    for (const Frame& frame : frames) {
        CallWriter w;
        frame(w);
        call(w, op::kFrameEnd, ++number);
        EXPECT_TRUE(writer.writeFrame(1, number, w.data(), w.size()));
    }
    EXPECT_TRUE(writer.close(error)) << error;
    return path;
}

std::string replayError(const std::string& path)
{
    ReplayOptions options;
    std::string error;
    EXPECT_FALSE(Replayer::run(path, options, error)) << path << " replayed";
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
    return error;
}

const Frame kGoodFrame = [](CallWriter& w) {
    triangleArray(w);
    call(w, op::glDrawArrays, GLenum(GL_TRIANGLES), GLint(0), GLsizei(3));
};

} // namespace

TEST(Replay, GoodStreamReplays)
{
    ASSERT_TRUE(kStyleNone);
    std::string path = writeCapture("good", {kGoodFrame, kGoodFrame});
    std::string error;
    EXPECT_TRUE(Replayer::run(path, ReplayOptions{}, error)) << error;
}

TEST(Replay, DrawPastItsArraysIsRefusedNamingFrameAndCall)
{
    std::string path = writeCapture("draw", {kGoodFrame, [](CallWriter& w) {
                                                 triangleArray(w);
                                                 call(w, op::glDrawArrays, GLenum(GL_TRIANGLES),
                                                      GLint(0), GLsizei(3000000));
                                             }});
    std::string error = replayError(path);
    EXPECT_NE(error.find("frame 2, call 3 (glDrawArrays)"), std::string::npos) << error;
    EXPECT_NE(error.find("reads vertices 0..2999999 of arrays holding 3"), std::string::npos)
        << error;
}

TEST(Replay, CommandRefusesBadCallAndExitsCleanly)
{
    std::string path =
        writeCapture("cli", {kGoodFrame, [](CallWriter& w) {
                                 triangleArray(w);
                                 call(w, op::glDrawArrays, GLenum(GL_POINTS), GLint(2), GLsizei(2));
                             }});
    ProcessResult p = runProcess(
        {binDir() + "/nprgl", "replay", "--style", "none", path, "-o", freshDir("replay_cli_out")});
    EXPECT_GT(p.exitCode, 0);
    EXPECT_LT(p.exitCode, 128) << "killed by a signal";
    EXPECT_NE(p.err.find("frame 2, call 3 (glDrawArrays)"), std::string::npos) << p.err;
    EXPECT_NE(p.err.find("reads vertices 2..3 of arrays holding 3"), std::string::npos) << p.err;
}

TEST(Replay, IndexOffsetWithoutElementBufferIsRefused)
{
    std::string path = writeCapture(
        "indices", {[](CallWriter& w) {
            triangleArray(w);
            // Mode 2: an offset into the element buffer, of which there is none: the driver
            // would take 0x1234 for a pointer.
            w.endPayload(beginCall(w, op::glDrawElements, GLenum(GL_TRIANGLES), GLsizei(3),
                                   GLenum(GL_UNSIGNED_INT), uint8_t(2), uint64_t(0x1234)));
        }});
    EXPECT_NE(replayError(path).find("call 3 (glDrawElements), chunk at"), std::string::npos);
    EXPECT_NE(replayError(path).find("without indices"), std::string::npos);
}

TEST(Replay, IndexPastItsArraysIsRefused)
{
    std::string path =
        writeCapture("index", {[](CallWriter& w) {
                         triangleArray(w);
                         const uint16_t indices[] = {0, 1, 40000};
                         size_t mark = beginCall(w, op::glDrawElements, GLenum(GL_TRIANGLES),
                                                 GLsizei(3), GLenum(GL_UNSIGNED_SHORT), uint8_t(1));
                         w.putBytes(indices, sizeof indices);
                         w.endPayload(mark);
                     }});
    EXPECT_NE(replayError(path).find("reads vertices 0..40000 of arrays holding 3"),
              std::string::npos);
}

// Mesa reads the enabled arrays at a negative glArrayElement index, before their start (a
// fuzzed capture crashed the replay this way).
TEST(Replay, NegativeArrayElementIsRefused)
{
    std::string path = writeCapture("element", {[](CallWriter& w) {
                                        triangleArray(w);
                                        call(w, op::glBegin, GLenum(GL_TRIANGLES));
                                        call(w, op::glArrayElement, GLint(-50397184));
                                        call(w, op::glEnd);
                                    }});
    std::string error = replayError(path);
    EXPECT_NE(error.find("(glArrayElement)"), std::string::npos) << error;
    EXPECT_NE(error.find("a negative index"), std::string::npos) << error;
}

// Nor the sign of glDrawArrays' first (a fuzzed capture crashed the replay this way).
TEST(Replay, NegativeFirstVertexIsRefused)
{
    std::string path = writeCapture("first", {[](CallWriter& w) {
                                        triangleArray(w);
                                        call(w, op::glDrawArrays, GLenum(GL_TRIANGLES),
                                             GLint(-512), GLsizei(255));
                                    }});
    std::string error = replayError(path);
    EXPECT_NE(error.find("(glDrawArrays)"), std::string::npos) << error;
    EXPECT_NE(error.find("a negative first"), std::string::npos) << error;
}

TEST(Replay, PointerIntoDeletedBufferIsRefused)
{
    std::string path =
        writeCapture("buffer", {[](CallWriter& w) {
                         call(w, op::glBindBuffer, GLenum(GL_ARRAY_BUFFER), GLuint(7));
                         size_t mark =
                             beginCall(w, op::glBufferData, GLenum(GL_ARRAY_BUFFER),
                                       GLsizeiptr(sizeof kTriangle), GLenum(GL_STATIC_DRAW));
                         w.putBytes(kTriangle, sizeof kTriangle);
                         w.endPayload(mark);
                         call(w, op::glEnableClientState, GLenum(GL_VERTEX_ARRAY));
                         w.endPayload(beginCall(w, op::glVertexPointer, GLint(3), GLenum(GL_FLOAT),
                                                GLsizei(0), uint64_t(0xdead0000)));
                         const GLuint name = 7;
                         mark = beginCall(w, op::glDeleteBuffers, GLsizei(1));
                         w.putBytes(&name, sizeof name);
                         w.endPayload(mark);
                         // The array's buffer binding is gone: its "pointer" is 0xdead0000.
                         call(w, op::glDrawArrays, GLenum(GL_TRIANGLES), GLint(0), GLsizei(3));
                     }});
    EXPECT_NE(replayError(path).find("call 5 (glDrawArrays)"), std::string::npos);
}

// glDrawRangeElements' range is a hint GL does not check: trigger-rally gives `end` one past
// its last vertex (of a vertex buffer), its indices all within. The replay refused every race
// frame ("reads vertices 0..3 of arrays holding 3"); it now draws such a call without the
// range, and still refuses indices past the arrays.
TEST(Replay, ARangeHintOnePastTheArraysIsDrawnWithoutIt)
{
    auto frame = [](uint16_t last) {
        return [last](CallWriter& w) {
            call(w, op::glBindBuffer, GLenum(GL_ARRAY_BUFFER), GLuint(7));
            size_t mark = beginCall(w, op::glBufferData, GLenum(GL_ARRAY_BUFFER),
                                    GLsizeiptr(sizeof kTriangle), GLenum(GL_STATIC_DRAW));
            w.putBytes(kTriangle, sizeof kTriangle);
            w.endPayload(mark);
            call(w, op::glEnableClientState, GLenum(GL_VERTEX_ARRAY));
            w.endPayload(beginCall(w, op::glVertexPointer, GLint(3), GLenum(GL_FLOAT),
                                   GLsizei(0), uint64_t(0)));
            const uint16_t indices[] = {0, 1, last};
            mark = beginCall(w, op::glDrawRangeElements, GLenum(GL_TRIANGLES), GLuint(0),
                             GLuint(3), GLsizei(3), GLenum(GL_UNSIGNED_SHORT), uint8_t(1));
            w.putBytes(indices, sizeof indices);
            w.endPayload(mark);
        };
    };
    std::string error;
    EXPECT_TRUE(Replayer::run(writeCapture("range_hint", {frame(2)}), ReplayOptions{}, error))
        << error;
    EXPECT_NE(replayError(writeCapture("range_index", {frame(3)}))
                  .find("reads vertices 0..3 of arrays holding 3"),
              std::string::npos);
}

TEST(Replay, ShortImageIsRefused)
{
    std::string path = writeCapture("image", {[](CallWriter& w) {
                                        const uint8_t pixels[16] = {};
                                        // 64x64 RGBA needs 16384 bytes; 16 are given.
                                        size_t mark = beginCall(
                                            w, op::glTexImage2D, GLenum(GL_TEXTURE_2D), GLint(0),
                                            GLint(GL_RGBA), GLsizei(64), GLsizei(64), GLint(0),
                                            GLenum(GL_RGBA), GLenum(GL_UNSIGNED_BYTE), uint8_t(1));
                                        w.putBytes(pixels, sizeof pixels);
                                        w.endPayload(mark);
                                    }});
    EXPECT_NE(replayError(path).find("glTexImage2D reads 16384 bytes of pixels from 16"),
              std::string::npos);
}

TEST(Replay, ListsThatMultiplyAreRefused)
{
    // Each list calls the one before it twice: list 40 would run 2^40 triangles.
    std::string path = writeCapture("lists", {[](CallWriter& w) {
                                        call(w, op::glNewList, GLuint(1), GLenum(GL_COMPILE));
                                        call(w, op::glRectf, 0.0f, 0.0f, 1.0f, 1.0f);
                                        call(w, op::glEndList);
                                        for (GLuint list = 2; list <= 40; ++list) {
                                            call(w, op::glNewList, list, GLenum(GL_COMPILE));
                                            call(w, op::glCallList, list - 1);
                                            call(w, op::glCallList, list - 1);
                                            call(w, op::glEndList);
                                        }
                                        call(w, op::glCallList, GLuint(40));
                                    }});
    std::string error = replayError(path);
    EXPECT_NE(error.find("(glCallList)"), std::string::npos) << error;
    EXPECT_NE(error.find("glCallList(40) would run"), std::string::npos) << error;
}

TEST(Replay, NameCountsAreBounded)
{
    std::string path = writeCapture("names", {[](CallWriter& w) {
                                        call(w, op::glDeleteLists, GLuint(1), GLsizei(0x7fffffff));
                                    }});
    EXPECT_NE(replayError(path).find("glDeleteLists of 2147483647 lists"), std::string::npos);
}

TEST(Replay, ImageSizesDoNotWrap)
{
    UnpackState unpack;
    unpack.rowLength = 0x7fffffff;
    unpack.imageHeight = 0x7fffffff;
    unpack.skipImages = 0x7fffffff;
    // 2^31 images of 2^31 rows of 2^33 bytes: no real image; it used to wrap to a small size.
    EXPECT_EQ(imageBytes(GL_RGBA, GL_FLOAT, 1, 1, 2, unpack), 0u);
    EXPECT_EQ(imageBytes(GL_RGBA, GL_UNSIGNED_BYTE, 2, 2, 1, UnpackState{}), 16u);
}

TEST(Replay, NestedBatchReferencesAreRefused)
{
    // Blob 0: a batch; blob 1: a batch that refers to blob 0 many times. Nesting a few such
    // levels ran an exponential number of calls; the recorder never nests them.
    CallWriter inner;
    call(inner, op::glBegin, GLenum(GL_POINTS));
    call(inner, op::glVertex2f, 0.0f, 0.0f);
    call(inner, op::glEnd);
    std::vector<uint8_t> innerBytes(inner.data(), inner.data() + inner.size());
    const uint64_t innerHash = capture::hashBlob(innerBytes.data(), innerBytes.size());
    CallWriter outer;
    for (int i = 0; i < 100; ++i)
        call(outer, op::kBatchRef, innerHash, uint64_t(inner.size()));
    std::vector<uint8_t> outerBytes(outer.data(), outer.data() + outer.size());
    const uint64_t outerHash = capture::hashBlob(outerBytes.data(), outerBytes.size());
    std::string path = writeCapture(
        "batches",
        {[&](CallWriter& w) { call(w, op::kBatchRef, innerHash, uint64_t(inner.size())); },
         [&](CallWriter& w) { call(w, op::kBatchRef, outerHash, uint64_t(outer.size())); }},
        {innerBytes, outerBytes});
    std::string error = replayError(path);
    EXPECT_NE(error.find("frame 2, call 0 (BatchRef)"), std::string::npos) << error;
    EXPECT_NE(error.find("batch reference inside a referenced batch"), std::string::npos) << error;
}

TEST(Replay, EvalCoordInsideBeginInAListIsRefused)
{
    // Found by fuzz_replay: Mesa's list compiler overran a heap buffer on this sequence.
    std::string path = writeCapture("eval", {[](CallWriter& w) {
                                        call(w, op::glNewList, GLuint(1), GLenum(GL_COMPILE));
                                        call(w, op::glBegin, GLenum(GL_TRIANGLES));
                                        call(w, op::glVertex3f, -1.0f, 0.0f, 0.0f);
                                        call(w, op::glEvalCoord2d, 0.5, 0.5);
                                        call(w, op::glEnd);
                                        call(w, op::glEndList);
                                    }});
    std::string error = replayError(path);
    EXPECT_NE(error.find("frame 1, call 3 (glEvalCoord2d)"), std::string::npos) << error;
}

TEST(Replay, ListEndedInsideBeginIsRefused)
{
    // Found by fuzz_replay: Mesa's list compiler overran a heap buffer ending a list whose
    // glBegin was still open (and on glCallList there).
    std::string path = writeCapture("dangling", {[](CallWriter& w) {
                                        call(w, op::glNewList, GLuint(1), GLenum(GL_COMPILE));
                                        call(w, op::glBegin, GLenum(GL_TRIANGLES));
                                        call(w, op::glColor3f, 1.0f, 0.0f, 0.0f);
                                        call(w, op::glVertex3f, -1.0f, 0.0f, 0.0f);
                                        call(w, op::glEndList);
                                    }});
    std::string error = replayError(path);
    EXPECT_NE(error.find("frame 1, call 4 (glEndList)"), std::string::npos) << error;
    EXPECT_NE(error.find("glEndList between glBegin and glEnd in a display list"),
              std::string::npos)
        << error;
}

// `nprgl replay --stats`: each frame's 3D polygon draws, styled and left by reason, on stdout
// (glxgears: its three gears, one held display list each, every frame), with no PNGs asked.
TEST(Replay, StatsCountEachFramesStyledAndLeftDraws)
{
    const std::string capture = std::string(NPRGL_TEST_SOURCE_DIR) + "/fixtures/glxgears.nprgl";
    ProcessResult p = runProcess({binDir() + "/nprgl", "replay", capture, "--stats", "--style",
                                  "toon", "--frames", "1-3"});
    ASSERT_EQ(p.exitCode, 0) << p.err;
    for (int f = 1; f <= 3; ++f) {
        EXPECT_NE(p.out.find("frame " + std::to_string(f) +
                             ": 3D polygon draws: 3 styled, 0 left as the program drew them\n"),
                  std::string::npos)
            << p.out;
    }
    ProcessResult none = runProcess({binDir() + "/nprgl", "replay", capture, "--stats",
                                     "--style", "none", "--frames", "1"});
    ASSERT_EQ(none.exitCode, 0) << none.err;
    EXPECT_NE(none.out.find("frame 1: 3D polygon draws: not styled (style none)"),
              std::string::npos)
        << none.out;
    ProcessResult neither = runProcess({binDir() + "/nprgl", "replay", capture});
    EXPECT_NE(neither.exitCode, 0);
    EXPECT_NE(neither.err.find("-o DIR or --stats is required"), std::string::npos)
        << neither.err;
}

// A capture of format 2 names no created shader or program: its replay says so once, as its
// names may meet the styles' own. One of format 3 (a Created after each) says nothing.
TEST(Replay, ACaptureThatDoesNotNameItsShadersSaysSo)
{
    auto frame = [](bool named) {
        return [named](CallWriter& w) {
            call(w, op::glCreateShader, GLenum(GL_VERTEX_SHADER));
            if (named) call(w, op::kCreated, uint32_t(7));
            call(w, op::glDeleteShader, GLuint(7));
            call(w, op::glCreateProgram);
            if (named) call(w, op::kCreated, uint32_t(8));
            call(w, op::glDeleteProgram, GLuint(8));
        };
    };
    const std::string warning = "does not say which names the program's shaders";
    for (bool named : {false, true}) {
        const std::string path =
            writeCapture(named ? "named" : "unnamed", {frame(named), frame(named)});
        ProcessResult p =
            runProcess({binDir() + "/nprgl", "replay", "--style", "none", path, "--stats"});
        EXPECT_EQ(p.exitCode, 0) << p.err;
        const size_t at = p.err.find(warning);
        if (named) {
            EXPECT_EQ(at, std::string::npos) << p.err;
        } else {
            ASSERT_NE(at, std::string::npos) << p.err;
            EXPECT_EQ(p.err.find(warning, at + 1), std::string::npos) << "said twice: " << p.err;
        }
    }
}

// Created names are bounded like glGen* counts: a capture announcing more is refused.
TEST(Replay, CreatedNamesAreBounded)
{
    const std::string path = writeCapture("created", {[](CallWriter& w) {
        for (uint32_t name = 1; name <= 20; ++name) call(w, op::kCreated, name);
    }});
    ReplayOptions options;
    options.limits.names = 16;
    std::string error;
    EXPECT_FALSE(Replayer::run(path, options, error));
    EXPECT_NE(error.find("more than 16 shader and program names"), std::string::npos) << error;
}
