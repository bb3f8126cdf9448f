#pragma once

#include "frame/ClientArrays.h"
#include "shim/Context.h"
#include "shim/ThreadState.h"
#include "stream/CallWriter.h"
#include "stream/GlSizes.h"

#include <array>
#include <unordered_map>
#include <utility>
#include <vector>

namespace nprgl {

class StreamSink;
class Context;


const char* opcodeNameOf(size_t opcode);

// Turns one context's calls into the Stream: the generated recording functions encode each
// call into writer() and call the driver; the hooks below follow the state needed to copy
// client memory that a draw reads (client arrays, index data, mapped buffers).
class Recorder {
public:
    // session: where frames go; null when only the compositor reads the Stream.
    Recorder(Context& ctx, StreamSink* session);
    ~Recorder();

    // The recorder of the current context (recording functions only run when it exists).
    // Inline: it is on the per-vertex path.
    static Recorder& current() { return *tThread.context->recorder(); }

    CallWriter& writer() { return mWriter; }
    // The calls held since the last frame ended.
    size_t streamBytes() const { return mWriter.size(); }
    bool hasSink() const { return mSession != nullptr; }
    // A call nprgl neither follows nor records: counted by name (the capture says it lacks
    // it) and a barrier for the compositor (what is held is drawn first, so order is kept).
    void countUncaptured(uint16_t opcode);
    // A query that reads rendered pixels (texture images, query results): a barrier only.
    void readback();
    // After glCreateShader or glCreateProgram: the name the program got (a kCreated pseudo-call).
    void created(GLuint name);
    // glReadPixels: a readback, or not captured when it writes into a pixel-pack buffer.
    void readPixels(uint16_t opcode);
    // Hands over the counts not reported yet (name, count).
    template <typename Fn>
    void takeUncaptured(Fn&& report);
    // Closes the frame: marks its end and hands it to the capture file.
    void endFrame(uint64_t frame);
    // The screenshot key's pair: the frame after the one ending now is kept whole (every
    // client array a draw reads sent in full, no batch blobs), with the client arrays as it
    // starts, for FrameReplay.
    void keepNextFrame();
    // Hands over the kept frame once it has ended; false before, and for a frame with draws
    // the recorder could not follow (its calls would not draw the same picture).
    bool takeKeptFrame(std::vector<uint8_t>& calls, ClientArrayState& start);
    bool frameKept() const { return mKeep == Keep::Kept; }
    // The client arrays as the program set them last.
    const ClientArrayState& clientArrays() const { return mState; }

    // Encodes an image or bitmap argument laid out by the current unpack state.
    void putImage(CallWriter& w, const void* pixels, GLenum format, GLenum type, GLsizei width,
                  GLsizei height, GLsizei depth);
    void putIndices(CallWriter& w, const void* indices, GLsizei count, GLenum type);
    // Encodes bytes read from the pixel-unpack buffer when one is bound (compressed images).
    void putUnpacked(CallWriter& w, const void* data, size_t bytes);

    // Immediate-mode batches: a glBegin..glEnd of kBatchBlobBytes or more is stored once as
    // a blob and referenced (programs re-send the same geometry every frame).
    static constexpr size_t kBatchBlobBytes = 512;
    void before_glBegin(GLenum mode);
    void after_glEnd();

    // State hooks, called before the call is recorded. The draw hooks return false when
    // nprgl cannot tell where the draw's arrays or indices are (a binding made through a
    // call it did not follow): nothing is read, and the draw goes to the driver unrecorded.
    bool before_glDrawArrays(GLenum mode, GLint first, GLsizei count);
    bool before_glDrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices);
    bool before_glDrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count,
                                    GLenum type, const void* indices);
    void before_glArrayElement(GLint i);
    bool before_glMultiDrawArrays(GLenum mode, const GLint* first, const GLsizei* count,
                                  GLsizei drawcount);
    void before_glEnableClientState(GLenum cap);
    void before_glDisableClientState(GLenum cap);
    void before_glClientActiveTexture(GLenum texture);
    void before_glEnableVertexAttribArray(GLuint index);
    void before_glDisableVertexAttribArray(GLuint index);
    void before_glBindBuffer(GLenum target, GLuint buffer);
    void before_glBufferData(GLenum target, GLsizeiptr size, const void* data, GLenum usage);
    void before_glBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size,
                                const void* data);
    void before_glDeleteBuffers(GLsizei n, const GLuint* buffers);
    void before_glPushClientAttrib(GLbitfield mask);
    void before_glPopClientAttrib();
    void before_glVertexPointer(GLint size, GLenum type, GLsizei stride, const void* p);
    void before_glNormalPointer(GLenum type, GLsizei stride, const void* p);
    void before_glColorPointer(GLint size, GLenum type, GLsizei stride, const void* p);
    void before_glSecondaryColorPointer(GLint size, GLenum type, GLsizei stride, const void* p);
    void before_glFogCoordPointer(GLenum type, GLsizei stride, const void* p);
    void before_glIndexPointer(GLenum type, GLsizei stride, const void* p);
    void before_glEdgeFlagPointer(GLsizei stride, const void* p);
    void before_glTexCoordPointer(GLint size, GLenum type, GLsizei stride, const void* p);
    void before_glVertexAttribPointer(GLuint index, GLint size, GLenum type,
                                      GLboolean normalized, GLsizei stride, const void* p);

    // Calls recorded by hand: they are replaced by equivalent recorded calls.
    void* glMapBuffer(GLenum target, GLenum access);
    void* glMapBufferRange(GLenum target, GLintptr offset, GLsizeiptr length,
                           GLbitfield access);
    void glFlushMappedBufferRange(GLenum target, GLintptr offset, GLsizeiptr length);
    GLboolean glUnmapBuffer(GLenum target);
    void glInterleavedArrays(GLenum format, GLsizei stride, const void* pointer);

private:
    void setArray(int slot, GLint size, GLenum type, GLsizei stride, const void* p);
    // Copies the elements [first, end) of every enabled client-memory array into the stream.
    void emitArrays(size_t first, size_t end);
    // Sends [offset, offset + bytes) of an array, minus what the replayer already has.
    void sendArray(int slot, const uint8_t* base, size_t offset, size_t bytes);
    void emitArrayRange(int slot, const uint8_t* base, size_t offset, size_t bytes);
    bool anyClientArray() const;
    // Does the driver's pixel-unpack binding agree with nprgl's? If not: counted, said once,
    // and the argument is recorded as null (nothing is read).
    bool unpackFollowed(CallWriter& w, const void* pixels);
    void emitElementArrays(GLenum mode, GLsizei count, GLenum type, const void* indices);
    // Asks the driver whether the client arrays the cache would read (and, for elements,
    // the element buffer) are what nprgl followed. False, counted and said once, when not.
    bool followed(uint16_t opcode, bool elements);
    bool clientArraysFollowed();
    bool vertexArrayObjectFollowed();
    // The driver's buffer and pointer of one array slot.
    void driverArray(int slot, GLint& buffer, void*& pointer) const;
    void noteUnfollowed(uint16_t opcode, bool uncaptured);
    void learnCaps();
    GLuint* bindingFor(GLenum target);
    UnpackState unpackState() const;

    struct Mapping {
        GLuint buffer = 0;
        uint8_t* pointer = nullptr; // the mapped range, which starts at offset
        size_t size = 0;
        size_t offset = 0;
        bool writable = false;
        bool explicitFlush = false; // written bytes are the flushed ranges, not the whole
    };
    // Records bytes a program wrote through a mapping as the glBufferSubData replay can do.
    void recordMappedWrite(GLenum target, size_t offset, const uint8_t* bytes, size_t size);

    Context& mContext;
    StreamSink* mSession;
    CallWriter mWriter;
    ClientArrayState mState;
    std::vector<ClientArrayState> mClientStack;
    std::unordered_map<GLuint, std::vector<uint8_t>> mBufferShadow; // for index ranges
    std::unordered_map<GLenum, Mapping> mMappings;
    // What the replayer's copy of each client array holds: bytes sent from
    // [mirrorBase + lo, mirrorBase + hi). Unchanged bytes are not sent again.
    struct Mirror {
        const uint8_t* base = nullptr;
        size_t lo = 0, hi = 0;
        std::vector<uint8_t> bytes; // indexed from lo
    };
    std::array<Mirror, kArraySlotCount> mMirrors;
    // What the driver can be asked (known once the context is current).
    bool mCapsKnown = false;
    bool mCanAskBuffers = false; // buffer objects exist (GL 1.5, ES)
    bool mCanAskFixed = false;   // fixed-function arrays exist (not core, not ES 2+)
    bool mCanAskAttribs = false; // generic attributes exist (GL 2.0, ES 2.0)
    bool mCanAskUnpack = false;  // pixel-unpack buffers exist (GL 2.1, ES 3.0)
    bool mCanAskVertexArray = false; // vertex array objects exist (compatibility 3.0)
    bool mCanAskRestart = false;      // GL_PRIMITIVE_RESTART exists (GL 3.1)
    bool mCanAskFixedRestart = false; // GL_PRIMITIVE_RESTART_FIXED_INDEX (GL 4.3, ES 3.0)
    bool mBeginFollowed = true;  // the arrays at the open glBegin were checked and followed
    bool mUnfollowedSaid = false;      // about draws
    bool mUnfollowedImageSaid = false; // about images
    std::vector<uint64_t> mUnfollowed; // draws whose arrays nprgl could not follow, by opcode
    uint64_t mUnfollowedImages = 0;    // images from an unpack buffer nprgl did not follow
    std::vector<uint64_t> mUncaptured;
    std::vector<uint64_t> mUncapturedReported;
    std::vector<std::pair<const char*, uint64_t>> mFrameUncaptured; // endFrame's scratch
    bool mStopped = false;
    size_t mBatchStart = SIZE_MAX; // writer offset of the open glBegin
    enum class Keep { None, Next, This, Kept } mKeep = Keep::None;
    std::vector<uint8_t> mKept;
    ClientArrayState mKeptStart;
    uint64_t mKeptUnfollowed = 0; // draws not followed before the kept frame
    bool mKeptWhole = false;
};

template <typename Fn>
void Recorder::takeUncaptured(Fn&& report)
{
    for (size_t i = 0; i < mUncaptured.size(); ++i) {
        if (mUncaptured[i] != mUncapturedReported[i]) {
            report(opcodeNameOf(i), mUncaptured[i] - mUncapturedReported[i]);
            mUncapturedReported[i] = mUncaptured[i];
        }
    }
}

} // namespace nprgl
