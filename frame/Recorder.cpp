#include "frame/Recorder.h"

#include "common/Log.h"
#include "frame/Compositor.h"
#include "frame/StreamSink.h"
#include "shim/Context.h"
#include "shim/RealGl.h"
#include "shim/ThreadState.h"
#include "stream/Opcodes.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>

namespace nprgl {

Recorder::Recorder(Context& ctx, StreamSink* session)
    : mContext(ctx), mSession(session), mUnfollowed(op::kCount, 0),
      mUncaptured(op::kCount, 0), mUncapturedReported(op::kCount, 0)
{
    // Without a sink (the compositor alone) large arguments stay inline.
    if (!session) return;
    mWriter.setBlobSink([session, &ctx](const void* data, size_t size) {
        const uint64_t hash = session->putBlob(ctx, data, size);
        if (Compositor* c = ctx.compositor()) c->keepBlob(hash, data, size);
        return hash;
    });
    session->attach(this);
}

Recorder::~Recorder()
{
    std::string unfollowed;
    for (size_t i = 0; i < mUnfollowed.size(); ++i) {
        if (!mUnfollowed[i]) continue;
        unfollowed += (unfollowed.empty() ? "" : ", ") + std::string(opcodeNameOf(i)) + " " +
                      std::to_string(mUnfollowed[i]);
    }
    if (mUnfollowedImages) {
        unfollowed += (unfollowed.empty() ? "" : ", ") + std::string("images ") +
                      std::to_string(mUnfollowedImages);
    }
    if (!unfollowed.empty()) {
        NPRGL_INFO("context %u: draws whose arrays nprgl could not follow: %s",
                   mContext.serial(), unfollowed.c_str());
    }
    if (!mSession) return;
    takeUncaptured([this](const char* name, uint64_t count) {
        mSession->addUncaptured(name, count);
    });
    mSession->detach(this);
}

const char* opcodeNameOf(size_t opcode) { return opcodeName(uint16_t(opcode)); }

void Recorder::countUncaptured(uint16_t opcode)
{
    ++mUncaptured[opcode];
    readback();
}

void Recorder::readback()
{
    if (Compositor* c = mContext.compositor()) c->barrier();
}

void Recorder::readPixels(uint16_t opcode)
{
    // Into client memory it only reads the frame; into a pixel-pack buffer (GL 2.1) it writes
    // a buffer whose new content the capture lacks.
    learnCaps();
    GLint pack = 0;
    if (mCanAskUnpack) gRealGl.glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &pack);
    if (pack) {
        countUncaptured(opcode);
    } else {
        readback();
    }
}

void Recorder::created(GLuint name)
{
    mWriter.op(op::kCreated);
    mWriter.put<uint32_t>(name);
}

void Recorder::endFrame(uint64_t frame)
{
    if (mSession) {
        // The frame names what it lacks (nprgl info and replay say which frames).
        mFrameUncaptured.clear();
        takeUncaptured([this](const char* name, uint64_t count) {
            mSession->addUncaptured(name, count);
            mFrameUncaptured.emplace_back(name, count);
        });
        if (!mFrameUncaptured.empty()) {
            mWriter.op(op::kUncaptured);
            const size_t mark = mWriter.beginPayload();
            mWriter.put<uint32_t>(uint32_t(mFrameUncaptured.size()));
            for (const auto& [name, count] : mFrameUncaptured) {
                mWriter.putString(name);
                mWriter.put<uint64_t>(count);
            }
            mWriter.endPayload(mark);
        }
    }
    mWriter.op(op::kFrameEnd);
    mWriter.put<uint64_t>(frame);
    if (mKeep == Keep::This || mKeep == Keep::Next) {
        // Draws not followed in the kept frame: its calls would not draw the same picture.
        const uint64_t unfollowed =
            std::accumulate(mUnfollowed.begin(), mUnfollowed.end(), uint64_t(0));
        if (mKeep == Keep::This) {
            mKept.assign(mWriter.data(), mWriter.data() + mWriter.size());
            mKeptWhole = unfollowed == mKeptUnfollowed;
            mKeep = Keep::Kept;
        } else {
            mKeptStart = mState;
            mKeptUnfollowed = unfollowed;
            mKeep = Keep::This;
        }
    }
    Compositor* compositor = mContext.compositor();
    if (compositor) compositor->syncStream();
    if (mSession) {
        if (!mStopped && !mSession->writeFrame(mContext, frame, mWriter.data(), mWriter.size())) {
            mStopped = true;
        }
    }
    mWriter.clear();
    if (compositor) compositor->streamCleared();
    mBatchStart = SIZE_MAX;
}

UnpackState Recorder::unpackState() const
{
    UnpackState s;
    // What the context does not know it does not have: OpenGL ES 1 and 2 know only the
    // alignment, GL 1.1 no image height or skipped images (asking would be a GL error).
    const ContextCaps& caps = mContext.caps();
    gRealGl.glGetIntegerv(GL_UNPACK_ALIGNMENT, &s.alignment);
    if (caps.es && caps.major < 3) return s;
    gRealGl.glGetIntegerv(GL_UNPACK_ROW_LENGTH, &s.rowLength);
    gRealGl.glGetIntegerv(GL_UNPACK_SKIP_PIXELS, &s.skipPixels);
    gRealGl.glGetIntegerv(GL_UNPACK_SKIP_ROWS, &s.skipRows);
    if (!caps.es && !caps.atLeast(1, 2)) return s;
    gRealGl.glGetIntegerv(GL_UNPACK_IMAGE_HEIGHT, &s.imageHeight);
    gRealGl.glGetIntegerv(GL_UNPACK_SKIP_IMAGES, &s.skipImages);
    return s;
}

void Recorder::learnCaps()
{
    if (mCapsKnown) return;
    mCapsKnown = true;
    const ContextCaps& caps = mContext.caps();
    if (caps.major == 0) return; // no version: ask nothing, read nothing unverifiable
    mCanAskBuffers = caps.es || caps.atLeast(1, 5);
    mCanAskFixed = !caps.core && !(caps.es && caps.major >= 2);
    mCanAskAttribs = caps.atLeast(2, 0);
    mCanAskUnpack = caps.es ? caps.atLeast(3, 0) : caps.atLeast(2, 1);
    // Core profiles have no client arrays to read, and always a vertex array object bound.
    mCanAskVertexArray = !caps.es && !caps.core && caps.atLeast(3, 0);
    // Asking for a capability the context does not have would leave the program a GL error.
    mCanAskRestart = !caps.es && caps.atLeast(3, 1);
    mCanAskFixedRestart = caps.es ? caps.atLeast(3, 0) : caps.atLeast(4, 3);
}

bool Recorder::unpackFollowed(CallWriter& w, const void* pixels)
{
    learnCaps();
    if (!pixels) return true;
    bool known = mBatchStart == SIZE_MAX; // inside glBegin the driver refuses the call
    if (known && mCanAskUnpack) {
        GLint bound = 0;
        gRealGl.glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &bound);
        known = GLuint(bound) == mState.unpackBuffer;
    }
    if (known) return true;
    // Bound through a call nprgl did not follow: `pixels` may be an offset. Read nothing.
    ++mUnfollowedImages;
    if (!mUnfollowedImageSaid) {
        mUnfollowedImageSaid = true;
        NPRGL_WARN("context %u: an image comes from a pixel-unpack buffer bound through a "
                   "call nprgl does not follow; it is recorded without its pixels",
                   mContext.serial());
    }
    w.put<uint8_t>(0);
    return false;
}

// Image arguments: u8 mode (0 null, 1 bytes, 2 offset into the pixel-unpack buffer).
void Recorder::putImage(CallWriter& w, const void* pixels, GLenum format, GLenum type,
                        GLsizei width, GLsizei height, GLsizei depth)
{
    if (!unpackFollowed(w, pixels)) return;
    if (mState.unpackBuffer) {
        w.put<uint8_t>(2);
        w.put<uint64_t>(reinterpret_cast<uintptr_t>(pixels));
    } else if (!pixels) {
        w.put<uint8_t>(0);
    } else {
        w.put<uint8_t>(1);
        w.putBytes(pixels, imageBytes(format, type, width, height, depth, unpackState()));
    }
}

void Recorder::putUnpacked(CallWriter& w, const void* data, size_t bytes)
{
    if (!unpackFollowed(w, data)) return;
    if (mState.unpackBuffer) {
        w.put<uint8_t>(2);
        w.put<uint64_t>(reinterpret_cast<uintptr_t>(data));
    } else if (!data) {
        w.put<uint8_t>(0);
    } else {
        w.put<uint8_t>(1);
        w.putBytes(data, bytes);
    }
}

void Recorder::putIndices(CallWriter& w, const void* indices, GLsizei count, GLenum type)
{
    if (mState.elementBuffer) {
        w.put<uint8_t>(2);
        w.put<uint64_t>(reinterpret_cast<uintptr_t>(indices));
    } else if (!indices || count <= 0) {
        w.put<uint8_t>(0);
    } else {
        w.put<uint8_t>(1);
        w.putBytes(indices, size_t(count) * indexBytes(type));
    }
}

bool Recorder::anyClientArray() const
{
    return std::any_of(mState.arrays.begin(), mState.arrays.end(),
                       [](const ClientArray& a) { return a.enabled && !a.inBuffer; });
}

void Recorder::driverArray(int slot, GLint& buffer, void*& pointer) const
{
    struct Query {
        GLenum buffer, pointer;
    };
    static const Query kFixed[kTexCoordArray0] = {
        {GL_VERTEX_ARRAY_BUFFER_BINDING, GL_VERTEX_ARRAY_POINTER},
        {GL_NORMAL_ARRAY_BUFFER_BINDING, GL_NORMAL_ARRAY_POINTER},
        {GL_COLOR_ARRAY_BUFFER_BINDING, GL_COLOR_ARRAY_POINTER},
        {GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING, GL_SECONDARY_COLOR_ARRAY_POINTER},
        {GL_FOG_COORD_ARRAY_BUFFER_BINDING, GL_FOG_COORD_ARRAY_POINTER},
        {GL_INDEX_ARRAY_BUFFER_BINDING, GL_INDEX_ARRAY_POINTER},
        {GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, GL_EDGE_FLAG_ARRAY_POINTER},
    };
    buffer = 0;
    pointer = nullptr;
    if (slot < kTexCoordArray0) {
        gRealGl.glGetIntegerv(kFixed[slot].buffer, &buffer);
        gRealGl.glGetPointerv(kFixed[slot].pointer, &pointer);
    } else if (slot < kAttribArray0) {
        // Texture coordinates are asked of the client-active unit.
        const GLint unit = GL_TEXTURE0 + (slot - kTexCoordArray0);
        GLint active = GL_TEXTURE0;
        gRealGl.glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &active);
        if (active != unit) gRealGl.glClientActiveTexture(GLenum(unit));
        gRealGl.glGetIntegerv(GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, &buffer);
        gRealGl.glGetPointerv(GL_TEXTURE_COORD_ARRAY_POINTER, &pointer);
        if (active != unit) gRealGl.glClientActiveTexture(GLenum(active));
    } else {
        const GLuint index = GLuint(slot - kAttribArray0);
        gRealGl.glGetVertexAttribiv(index, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &buffer);
        gRealGl.glGetVertexAttribPointerv(index, GL_VERTEX_ATTRIB_ARRAY_POINTER, &pointer);
    }
}

bool Recorder::clientArraysFollowed()
{
    learnCaps();
    if (!mContext.caps().major) return !anyClientArray(); // nothing can be asked
    if (!mCanAskBuffers) return true; // no buffer objects: every pointer is client memory
    GLint maxUnits = -1;
    for (int slot = 0; slot < kArraySlotCount; ++slot) {
        const ClientArray& a = mState.arrays[slot];
        if (!a.enabled || a.inBuffer) continue;
        if (slot < kAttribArray0 && !mCanAskFixed) return false;
        // ES 1 has only these four fixed arrays (asking for the others is an error).
        if (mContext.caps().es && slot < kTexCoordArray0 && slot != kVertexArray &&
            slot != kNormalArray && slot != kColorArray) {
            return false;
        }
        if (slot >= kAttribArray0 && !mCanAskAttribs) return false;
        if (slot >= kTexCoordArray0 && slot < kAttribArray0) {
            if (maxUnits < 0) {
                const ContextCaps& caps = mContext.caps();
                gRealGl.glGetIntegerv(caps.es || !caps.atLeast(2, 0) ? GL_MAX_TEXTURE_UNITS
                                                                    : GL_MAX_TEXTURE_COORDS,
                                      &maxUnits);
            }
            if (slot - kTexCoordArray0 >= maxUnits) return false;
        }
        // The array nprgl would copy must be the driver's, in client memory: a buffer bound
        // (or a pointer set, a vertex array object bound) through a call nprgl did not
        // follow makes the cached pointer a buffer offset or a stale address.
        GLint buffer = 0;
        void* pointer = nullptr;
        driverArray(slot, buffer, pointer);
        if (buffer != 0 || pointer != a.pointer) return false;
    }
    return true;
}

bool Recorder::vertexArrayObjectFollowed()
{
    learnCaps();
    if (!mCanAskVertexArray) return true;
    // glBindVertexArray (GL 3.0) is not followed: while a vertex array object is bound, every
    // array and the element buffer may be other than nprgl's cache says.
    GLint bound = 0;
    gRealGl.glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &bound);
    return bound == 0;
}

bool Recorder::followed(uint16_t opcode, bool elements)
{
    // Inside glBegin..glEnd nothing may be asked, and the driver refuses the draw anyway.
    bool ok = mBatchStart == SIZE_MAX && vertexArrayObjectFollowed() && clientArraysFollowed();
    if (ok && elements && mCanAskBuffers) {
        GLint bound = 0;
        gRealGl.glGetIntegerv(GL_ELEMENT_ARRAY_BUFFER_BINDING, &bound);
        ok = GLuint(bound) == mState.elementBuffer;
    }
    // With primitive restart on, one index value cuts strips instead of naming a vertex:
    // neither the array range nor the mesh reconstruction may read it as one.
    if (ok && elements && mCanAskRestart) ok = !gRealGl.glIsEnabled(GL_PRIMITIVE_RESTART);
    if (ok && elements && mCanAskFixedRestart) {
        ok = !gRealGl.glIsEnabled(GL_PRIMITIVE_RESTART_FIXED_INDEX);
    }
    if (!ok) {
        noteUnfollowed(opcode, true);
        // The draw goes to the driver now: what is held is drawn before it.
        if (Compositor* compositor = mContext.compositor()) compositor->barrier();
    }
    return ok;
}

void Recorder::noteUnfollowed(uint16_t opcode, bool uncaptured)
{
    ++mUnfollowed[opcode];
    if (uncaptured) ++mUncaptured[opcode];
    if (mUnfollowedSaid) return;
    mUnfollowedSaid = true;
    NPRGL_WARN("context %u: %s draws from arrays or indices bound through a call nprgl does not "
               "follow, or with primitive restart; such draws go to the driver unrecorded and "
               "unstyled",
               mContext.serial(), opcodeNameOf(opcode));
}

void Recorder::emitArrays(size_t first, size_t end)
{
    if (end <= first) return;
    for (int slot = 0; slot < kArraySlotCount; ++slot) {
        const ClientArray& a = mState.arrays[slot];
        if (!a.enabled || a.inBuffer || !a.pointer || !a.elementBytes()) continue;
        const size_t stride = a.effectiveStride();
        const size_t offset = first * stride;
        const size_t bytes = (end - first - 1) * stride + a.elementBytes();
        sendArray(slot, a.pointer, offset, bytes);
    }
}

void Recorder::sendArray(int slot, const uint8_t* base, size_t offset, size_t bytes)
{
    Mirror& m = mMirrors[slot];
    // A kept frame is replayed on its own: no data from before it.
    if (m.base != base || mKeep == Keep::This) m = Mirror{base, 0, 0, {}};
    const size_t end = offset + bytes;
    if (m.hi <= m.lo || offset > m.hi || end < m.lo) {
        // Nothing known near this range: send it all and remember only it.
        emitArrayRange(slot, base, offset, bytes);
        m.bytes.assign(base + offset, base + end);
        m.lo = offset;
        m.hi = end;
        return;
    }
    // Inside the known span, send only what changed since the replayer last saw it (often
    // nothing: several draws of one array, or static geometry drawn every frame).
    const size_t in0 = std::max(offset, m.lo), in1 = std::min(end, m.hi);
    const uint8_t* now = base + in0;
    uint8_t* seen = m.bytes.data() + (in0 - m.lo);
    size_t lo = 0, hi = in1 - in0;
    while (lo < hi && now[lo] == seen[lo]) ++lo;
    while (hi > lo && now[hi - 1] == seen[hi - 1]) --hi;
    if (lo < hi) {
        emitArrayRange(slot, base, in0 + lo, hi - lo);
        std::memcpy(seen + lo, now + lo, hi - lo);
    }
    // Outside it, send everything and grow the known span.
    if (offset < m.lo) emitArrayRange(slot, base, offset, m.lo - offset);
    if (end > m.hi) emitArrayRange(slot, base, m.hi, end - m.hi);
    if (offset < m.lo || end > m.hi) {
        const size_t lo2 = std::min(offset, m.lo), hi2 = std::max(end, m.hi);
        std::vector<uint8_t> merged(hi2 - lo2);
        std::memcpy(merged.data() + (m.lo - lo2), m.bytes.data(), m.hi - m.lo);
        if (offset < m.lo) std::memcpy(merged.data(), base + offset, m.lo - offset);
        if (end > m.hi) std::memcpy(merged.data() + (m.hi - lo2), base + m.hi, end - m.hi);
        m.bytes.swap(merged);
        m.lo = lo2;
        m.hi = hi2;
    }
}

void Recorder::keepNextFrame()
{
    if (mKeep == Keep::None || mKeep == Keep::Kept) mKeep = Keep::Next;
}

bool Recorder::takeKeptFrame(std::vector<uint8_t>& calls, ClientArrayState& start)
{
    if (mKeep != Keep::Kept) return false;
    mKeep = Keep::None;
    calls.swap(mKept);
    mKept = {};
    start = mKeptStart;
    return mKeptWhole;
}

void Recorder::emitArrayRange(int slot, const uint8_t* base, size_t offset, size_t bytes)
{
    mWriter.op(op::kArrayData);
    const size_t mark = mWriter.beginPayload();
    mWriter.put<uint8_t>(static_cast<uint8_t>(slot));
    mWriter.put<uint64_t>(offset);
    mWriter.putBytes(base + offset, bytes);
    mWriter.endPayload(mark);
}

void Recorder::before_glBegin(GLenum)
{
    // glArrayElement inside cannot ask the driver: the arrays are checked once here.
    mBeginFollowed = !anyClientArray() || (vertexArrayObjectFollowed() && clientArraysFollowed());
    if (!mBeginFollowed) noteUnfollowed(op::glBegin, false); // the batch itself is recorded
    mBatchStart = mWriter.size();
}

void Recorder::after_glEnd()
{
    const size_t start = mBatchStart;
    mBatchStart = SIZE_MAX;
    if (start == SIZE_MAX || start > mWriter.size()) return;
    const size_t bytes = mWriter.size() - start;
    if (bytes < kBatchBlobBytes || mStopped || !mSession || mKeep == Keep::This) return;
    // The compositor follows the batch before it becomes a reference it could not resolve.
    Compositor* compositor = mContext.compositor();
    if (compositor) compositor->syncStream();
    // The calls from glBegin to glEnd become one reference to a blob with the same bytes.
    const uint64_t hash = mSession->putBlob(mContext, mWriter.data() + start, bytes);
    mWriter.truncate(start);
    mWriter.op(op::kBatchRef);
    mWriter.put<uint64_t>(hash);
    mWriter.put<uint64_t>(bytes);
    if (compositor) compositor->streamRewritten(mWriter.size());
}

bool Recorder::before_glDrawArrays(GLenum, GLint first, GLsizei count)
{
    if (!followed(op::glDrawArrays, false)) return false;
    if (first >= 0 && count > 0 && anyClientArray())
        emitArrays(size_t(first), size_t(first) + count);
    return true;
}

bool Recorder::before_glDrawElements(GLenum mode, GLsizei count, GLenum type,
                                     const void* indices)
{
    if (!followed(op::glDrawElements, true)) return false;
    emitElementArrays(mode, count, type, indices);
    return true;
}

void Recorder::emitElementArrays(GLenum, GLsizei count, GLenum type, const void* indices)
{
    const size_t width = indexBytes(type);
    if (count <= 0 || !width || !anyClientArray()) return;
    const uint8_t* data = static_cast<const uint8_t*>(indices);
    if (mState.elementBuffer) {
        auto it = mBufferShadow.find(mState.elementBuffer);
        size_t offset = reinterpret_cast<uintptr_t>(indices);
        if (it == mBufferShadow.end() || offset + size_t(count) * width > it->second.size()) {
            return; // the driver refuses this draw
        }
        data = it->second.data() + offset;
    }
    if (!data) return;
    size_t lo = std::numeric_limits<size_t>::max(), hi = 0;
    for (GLsizei i = 0; i < count; ++i) {
        size_t index = width == 1   ? data[i]
                       : width == 2 ? reinterpret_cast<const uint16_t*>(data)[i]
                                    : reinterpret_cast<const uint32_t*>(data)[i];
        lo = std::min(lo, index);
        hi = std::max(hi, index);
    }
    emitArrays(lo, hi + 1);
}

bool Recorder::before_glDrawRangeElements(GLenum mode, GLuint, GLuint, GLsizei count,
                                          GLenum type, const void* indices)
{
    if (!followed(op::glDrawRangeElements, true)) return false;
    // The range is only a hint the program may get wrong; the indices are the truth.
    emitElementArrays(mode, count, type, indices);
    return true;
}

void Recorder::before_glArrayElement(GLint i)
{
    if (i < 0 || !anyClientArray()) return;
    // Inside glBegin..glEnd the check made at glBegin stands (nothing may be asked there).
    const bool ok = mBatchStart != SIZE_MAX
                        ? mBeginFollowed
                        : vertexArrayObjectFollowed() && clientArraysFollowed();
    if (ok) emitArrays(size_t(i), size_t(i) + 1);
}

bool Recorder::before_glMultiDrawArrays(GLenum, const GLint* first, const GLsizei* count,
                                        GLsizei drawcount)
{
    if (!followed(op::glMultiDrawArrays, false)) return false;
    if (!first || !count || drawcount <= 0 || !anyClientArray()) return true;
    size_t lo = std::numeric_limits<size_t>::max(), hi = 0;
    for (GLsizei i = 0; i < drawcount; ++i) {
        if (first[i] < 0 || count[i] <= 0) continue;
        lo = std::min(lo, size_t(first[i]));
        hi = std::max(hi, size_t(first[i]) + count[i]);
    }
    if (hi > lo) emitArrays(lo, hi);
    return true;
}

void Recorder::before_glEnableClientState(GLenum cap)
{
    int slot = arraySlotForCap(cap, mState.clientActiveTexture);
    if (slot >= 0) mState.arrays[slot].enabled = true;
}

void Recorder::before_glDisableClientState(GLenum cap)
{
    int slot = arraySlotForCap(cap, mState.clientActiveTexture);
    if (slot >= 0) mState.arrays[slot].enabled = false;
}

void Recorder::before_glClientActiveTexture(GLenum texture)
{
    if (texture >= GL_TEXTURE0 && texture < GL_TEXTURE0 + 8) {
        mState.clientActiveTexture = int(texture - GL_TEXTURE0);
    }
}

void Recorder::before_glEnableVertexAttribArray(GLuint index)
{
    if (index < 16) mState.arrays[kAttribArray0 + index].enabled = true;
}

void Recorder::before_glDisableVertexAttribArray(GLuint index)
{
    if (index < 16) mState.arrays[kAttribArray0 + index].enabled = false;
}

GLuint* Recorder::bindingFor(GLenum target)
{
    switch (target) {
    case GL_ARRAY_BUFFER: return &mState.arrayBuffer;
    case GL_ELEMENT_ARRAY_BUFFER: return &mState.elementBuffer;
    case GL_PIXEL_UNPACK_BUFFER: return &mState.unpackBuffer;
    default: return nullptr;
    }
}

void Recorder::before_glBindBuffer(GLenum target, GLuint buffer)
{
    if (GLuint* binding = bindingFor(target)) *binding = buffer;
}

namespace {

GLuint boundBuffer(GLenum target)
{
    GLenum query = target == GL_ARRAY_BUFFER           ? GL_ARRAY_BUFFER_BINDING
                   : target == GL_ELEMENT_ARRAY_BUFFER ? GL_ELEMENT_ARRAY_BUFFER_BINDING
                   : target == GL_PIXEL_UNPACK_BUFFER  ? GL_PIXEL_UNPACK_BUFFER_BINDING
                   : target == GL_PIXEL_PACK_BUFFER    ? GL_PIXEL_PACK_BUFFER_BINDING
                                                       : 0;
    GLint id = 0;
    if (query) gRealGl.glGetIntegerv(query, &id);
    return GLuint(id);
}

} // namespace

void Recorder::before_glBufferData(GLenum target, GLsizeiptr size, const void* data, GLenum)
{
    GLuint buffer = boundBuffer(target);
    if (!buffer || size < 0) return;
    std::vector<uint8_t>& shadow = mBufferShadow[buffer];
    if (data) {
        shadow.assign(static_cast<const uint8_t*>(data), static_cast<const uint8_t*>(data) + size);
    } else {
        shadow.assign(size_t(size), 0);
    }
}

void Recorder::before_glBufferSubData(GLenum target, GLintptr offset, GLsizeiptr size,
                                      const void* data)
{
    auto it = mBufferShadow.find(boundBuffer(target));
    if (it == mBufferShadow.end() || !data || offset < 0 || size < 0 ||
        size_t(offset) + size_t(size) > it->second.size()) {
        return;
    }
    std::copy_n(static_cast<const uint8_t*>(data), size, it->second.begin() + offset);
}

void Recorder::before_glDeleteBuffers(GLsizei n, const GLuint* buffers)
{
    for (GLsizei i = 0; buffers && i < n; ++i) {
        mBufferShadow.erase(buffers[i]);
        for (GLuint* b : {&mState.arrayBuffer, &mState.elementBuffer, &mState.unpackBuffer}) {
            if (*b == buffers[i]) *b = 0;
        }
    }
}

void Recorder::before_glPushClientAttrib(GLbitfield) { mClientStack.push_back(mState); }

void Recorder::before_glPopClientAttrib()
{
    if (mClientStack.empty()) return; // the driver raises GL_STACK_UNDERFLOW
    mState = mClientStack.back();
    mClientStack.pop_back();
}

void Recorder::setArray(int slot, GLint size, GLenum type, GLsizei stride, const void* p)
{
    ClientArray& a = mState.arrays[slot];
    a.size = size;
    a.type = type;
    a.stride = stride;
    a.pointer = static_cast<const uint8_t*>(p);
    a.inBuffer = mState.arrayBuffer != 0;
}

void Recorder::before_glVertexPointer(GLint size, GLenum type, GLsizei stride, const void* p)
{
    setArray(kVertexArray, size, type, stride, p);
}

void Recorder::before_glNormalPointer(GLenum type, GLsizei stride, const void* p)
{
    setArray(kNormalArray, 3, type, stride, p);
}

void Recorder::before_glColorPointer(GLint size, GLenum type, GLsizei stride, const void* p)
{
    setArray(kColorArray, size, type, stride, p);
}

void Recorder::before_glSecondaryColorPointer(GLint size, GLenum type, GLsizei stride,
                                              const void* p)
{
    setArray(kSecondaryColorArray, size, type, stride, p);
}

void Recorder::before_glFogCoordPointer(GLenum type, GLsizei stride, const void* p)
{
    setArray(kFogCoordArray, 1, type, stride, p);
}

void Recorder::before_glIndexPointer(GLenum type, GLsizei stride, const void* p)
{
    setArray(kIndexArray, 1, type, stride, p);
}

void Recorder::before_glEdgeFlagPointer(GLsizei stride, const void* p)
{
    setArray(kEdgeFlagArray, 1, GL_UNSIGNED_BYTE, stride, p);
}

void Recorder::before_glTexCoordPointer(GLint size, GLenum type, GLsizei stride, const void* p)
{
    setArray(kTexCoordArray0 + mState.clientActiveTexture, size, type, stride, p);
}

void Recorder::before_glVertexAttribPointer(GLuint index, GLint size, GLenum type, GLboolean,
                                            GLsizei stride, const void* p)
{
    if (index < 16) setArray(kAttribArray0 + index, size, type, stride, p);
}

void* Recorder::glMapBuffer(GLenum target, GLenum access)
{
    void* p = gRealGl.glMapBuffer(target, access);
    if (p) {
        GLint size = 0;
        gRealGl.glGetBufferParameteriv(target, GL_BUFFER_SIZE, &size);
        mMappings[target] = Mapping{boundBuffer(target), static_cast<uint8_t*>(p), size_t(size),
                                    0, access != GL_READ_ONLY, false};
    }
    return p;
}

void* Recorder::glMapBufferRange(GLenum target, GLintptr offset, GLsizeiptr length,
                                 GLbitfield access)
{
    void* p = gRealGl.glMapBufferRange(target, offset, length, access);
    if (p && offset >= 0 && length >= 0) {
        // A persistent mapping is written while the driver draws from it, with no unmap or
        // flush to say when: nprgl cannot see those writes, and the capture says so.
        if (access & GL_MAP_PERSISTENT_BIT) countUncaptured(op::glMapBufferRange);
        mMappings[target] = Mapping{boundBuffer(target), static_cast<uint8_t*>(p),
                                    size_t(length), size_t(offset),
                                    (access & GL_MAP_WRITE_BIT) != 0,
                                    (access & GL_MAP_FLUSH_EXPLICIT_BIT) != 0};
    }
    return p;
}

void Recorder::glFlushMappedBufferRange(GLenum target, GLintptr offset, GLsizeiptr length)
{
    auto it = mMappings.find(target);
    if (it != mMappings.end() && it->second.writable && offset >= 0 && length >= 0 &&
        size_t(offset) <= it->second.size && size_t(length) <= it->second.size - offset) {
        const Mapping& m = it->second;
        recordMappedWrite(target, m.offset + size_t(offset), m.pointer + offset, size_t(length));
    }
    gRealGl.glFlushMappedBufferRange(target, offset, length);
}

void Recorder::recordMappedWrite(GLenum target, size_t offset, const uint8_t* bytes,
                                 size_t size)
{
    before_glBufferSubData(target, GLintptr(offset), GLsizeiptr(size), bytes);
    mWriter.op(op::glBufferSubData);
    const size_t mark = mWriter.beginPayload();
    mWriter.put<GLenum>(target);
    mWriter.put<GLintptr>(GLintptr(offset));
    mWriter.put<GLsizeiptr>(GLsizeiptr(size));
    mWriter.putBytes(bytes, size);
    mWriter.endPayload(mark);
}

GLboolean Recorder::glUnmapBuffer(GLenum target)
{
    // Replay cannot map: what the program wrote is recorded as glBufferSubData instead.
    auto it = mMappings.find(target);
    if (it != mMappings.end()) {
        const Mapping m = it->second;
        mMappings.erase(it);
        if (m.writable && !m.explicitFlush && m.pointer) {
            recordMappedWrite(target, m.offset, m.pointer, m.size);
        }
    }
    return gRealGl.glUnmapBuffer(target);
}

void Recorder::glInterleavedArrays(GLenum format, GLsizei stride, const void* pointer)
{
    // The driver is the oracle: let it set the arrays, then record the equivalent calls.
    gRealGl.glInterleavedArrays(format, stride, pointer);
    struct Fixed {
        GLenum cap;
        GLenum sizeQuery, typeQuery, strideQuery, pointerQuery;
        uint16_t pointerOp;
    };
    static const Fixed kArrays[] = {
        {GL_VERTEX_ARRAY, GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY_STRIDE,
         GL_VERTEX_ARRAY_POINTER, op::glVertexPointer},
        {GL_NORMAL_ARRAY, 0, GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE,
         GL_NORMAL_ARRAY_POINTER, op::glNormalPointer},
        {GL_COLOR_ARRAY, GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE,
         GL_COLOR_ARRAY_POINTER, op::glColorPointer},
        {GL_TEXTURE_COORD_ARRAY, GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE,
         GL_TEXTURE_COORD_ARRAY_STRIDE, GL_TEXTURE_COORD_ARRAY_POINTER, op::glTexCoordPointer},
        {GL_INDEX_ARRAY, 0, 0, 0, 0, 0},
        {GL_EDGE_FLAG_ARRAY, 0, 0, 0, 0, 0},
    };
    for (const Fixed& f : kArrays) {
        bool enabled = gRealGl.glIsEnabled(f.cap);
        (enabled ? before_glEnableClientState(f.cap) : before_glDisableClientState(f.cap));
        mWriter.op(enabled ? op::glEnableClientState : op::glDisableClientState);
        mWriter.put<GLenum>(f.cap);
        if (!enabled || !f.pointerOp) continue;
        GLint size = 3, type = 0, arrayStride = 0;
        void* p = nullptr;
        if (f.sizeQuery) gRealGl.glGetIntegerv(f.sizeQuery, &size);
        gRealGl.glGetIntegerv(f.typeQuery, &type);
        gRealGl.glGetIntegerv(f.strideQuery, &arrayStride);
        gRealGl.glGetPointerv(f.pointerQuery, &p);
        mWriter.op(f.pointerOp);
        const size_t mark = mWriter.beginPayload();
        if (f.pointerOp != op::glNormalPointer) mWriter.put<GLint>(size);
        mWriter.put<GLenum>(GLenum(type));
        mWriter.put<GLsizei>(arrayStride);
        mWriter.put<uint64_t>(reinterpret_cast<uintptr_t>(p));
        mWriter.endPayload(mark);
        int slot = arraySlotForCap(f.cap, mState.clientActiveTexture);
        if (slot >= 0) setArray(slot, size, GLenum(type), arrayStride, p);
    }
}

} // namespace nprgl
