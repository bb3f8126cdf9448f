#include "replay/ReplaySink.h"

#include "common/Log.h"
#include "frame/ClientArrays.h"
#include "shim/RealGl.h"
#include "stream/CallDecoder.h"
#include "stream/GlSizes.h"
#include "stream/Opcodes.h"

#include <cctype>
#include <cmath>
#include <limits>
#include <string_view>
#include <utility>

namespace nprgl {

namespace {

constexpr uint64_t kNoArrays = std::numeric_limits<uint64_t>::max();

uint64_t satAdd(uint64_t a, uint64_t b) { return a > kNoArrays - b ? kNoArrays : a + b; }

// Calls that give a vertex or its attributes (what belongs between glBegin and glEnd),
// and glEnd.
bool vertexCall(uint16_t opcode)
{
    const char* name = opcodeName(opcode);
    if (!name) return false;
    const std::string_view n(name);
    auto numbered = [&](std::string_view prefix) {
        return n.starts_with(prefix) && n.size() > prefix.size() &&
               std::isdigit(static_cast<unsigned char>(n[prefix.size()]));
    };
    return numbered("glVertex") || numbered("glVertexAttrib") || numbered("glColor") ||
           numbered("glSecondaryColor") || numbered("glNormal") || numbered("glTexCoord") ||
           numbered("glMultiTexCoord") || n.starts_with("glMaterial") || n == "glFogCoordf" ||
           n == "glFogCoordfv" || n == "glFogCoordd" || n == "glFogCoorddv" || n == "glEdgeFlag" ||
           n == "glEdgeFlagv" || (n.starts_with("glIndex") && n.find_first_of("dfisu", 7) == 7) ||
           n == "glArrayElement" || n == "glEnd";
}

} // namespace

ReplaySink::ReplaySink(ShadowArrays& arrays, const ReplayLimits& limits,
                       std::function<bool(uint64_t)> frameEnd)
    : mArrays(arrays), mLimits(limits), mFrameEnd(std::move(frameEnd))
{
}

bool ReplaySink::refuse(std::string message)
{
    if (mError.empty()) mError = std::move(message);
    return false;
}

bool ReplaySink::before(uint16_t opcode)
{
    mOpcode = opcode;
    mWork = 1;
    if (!chargeWork(1)) return false; // batch references may run a blob's calls many times
    if (mMadeUnnamed) {
        // A capture of format 2 does not say which name the program got.
        mMadeUnnamed = false;
        if (!mWarnedUnnamed) {
            NPRGL_WARN("this capture does not say which names the program's shaders and "
                       "programs got (its format is older than version 3): in a style, "
                       "they may take the names of the styles' own programs and draw wrongly; "
                       "record it again");
            mWarnedUnnamed = true;
        }
    }
    // Mesa's list compiler overruns heap buffers on several calls after a glBegin it
    // compiled (glEndList, glCallList, glEvalCoord...; found by fuzz_replay). Programs only
    // give vertices and their attributes there.
    if (mListBegun && !vertexCall(opcode))
        return refuse(std::string(opcodeName(opcode)) + " between glBegin and glEnd in a " +
                      "display list");
    // The arrays glArrayElement reads between glBegin and glEnd, asked while the driver
    // still answers.
    if (opcode == op::glBegin && !mUsesValid && idle()) queryArrays();
    return true;
}

void ReplaySink::after(uint16_t opcode)
{
    mLists.addWork(mWork);
    // glPopClientAttrib puts back the client unit that was active at its push.
    if (opcode == op::glClientActiveTexture || opcode == op::glPopClientAttrib) {
        GLint unit = GL_TEXTURE0;
        gRealGl.glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &unit);
        mClientActiveTexture = unit - GL_TEXTURE0;
    }
    switch (opcode) {
    case op::glBegin:
        mListBegun = mLists.compiling();
        break;
    case op::glEnd:
    case op::glEndList:
        mListBegun = false;
        break;
    // What decides where a draw's vertices come from and how many there are.
    case op::glVertexPointer:
    case op::glNormalPointer:
    case op::glColorPointer:
    case op::glSecondaryColorPointer:
    case op::glFogCoordPointer:
    case op::glIndexPointer:
    case op::glEdgeFlagPointer:
    case op::glTexCoordPointer:
    case op::glVertexAttribPointer:
    case op::glEnableClientState:
    case op::glDisableClientState:
    case op::glEnableVertexAttribArray:
    case op::glDisableVertexAttribArray:
    case op::glPushClientAttrib:
    case op::glPopClientAttrib:
    case op::glBindBuffer:
    case op::glBufferData:
    case op::glDeleteBuffers:
        mUsesValid = false;
        break;
    default:
        break;
    }
}

const void* ReplaySink::clientPointer(uint64_t value, int attribIndex)
{
    GLint buffer = 0;
    gRealGl.glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &buffer);
    if (buffer) return reinterpret_cast<const void*>(uintptr_t(value));
    const int slot = arraySlotForPointerCall(mOpcode, attribIndex, mClientActiveTexture);
    return slot >= 0 ? mArrays.base(slot) : nullptr;
}

bool ReplaySink::pseudo(CallReader& r, uint16_t opcode)
{
    if (opcode == op::kFrameEnd) {
        uint64_t frame = r.get<uint64_t>();
        if (!r.ok()) return false;
        for (const auto& [name, count] : mFrameUncaptured) {
            Uncaptured& u = mUncaptured[name];
            u.calls += count;
            u.frames.push_back(frame);
        }
        mFrameUncaptured.clear();
        const bool ok = mFrameEnd(frame);
        mCleared = false;
        return ok;
    }
    if (opcode == op::kArrayData) return mArrays.apply(r);
    if (opcode == op::kBatchRef) return expandBatchRef(r, *this, mDepth);
    if (opcode == op::kUncaptured) {
        CallReader::Uncaptured calls;
        if (!r.getUncaptured(calls)) return false;
        for (auto& [name, count] : calls) mFrameUncaptured.emplace_back(std::move(name), count);
        return true;
    }
    if (opcode == op::kCreated) {
        const GLuint recorded = r.get<uint32_t>();
        if (!r.ok()) return false;
        if (mObjectNames.size() >= mLimits.names && !mObjectNames.contains(recorded)) {
            r.fail("more than " + std::to_string(mLimits.names) + " shader and program names");
            return false;
        }
        mObjectNames[recorded] = mMade; // 0 where the create failed here: no object
        mMade = 0;
        mMadeUnnamed = false;
        return true;
    }
    r.fail("unknown opcode " + std::to_string(opcode));
    return false;
}

bool ReplaySink::idle() const
{
    GLint mode = -1;
    gRealGl.glGetIntegerv(GL_MATRIX_MODE, &mode);
    return mode != -1;
}

GLint ReplaySink::getInt(GLenum pname) const
{
    GLint v = 0;
    gRealGl.glGetIntegerv(pname, &v);
    return v;
}

uint64_t ReplaySink::bufferSize(GLenum target, GLuint buffer) const
{
    const GLenum binding = target == GL_ARRAY_BUFFER           ? GL_ARRAY_BUFFER_BINDING
                           : target == GL_ELEMENT_ARRAY_BUFFER ? GL_ELEMENT_ARRAY_BUFFER_BINDING
                                                               : GL_PIXEL_UNPACK_BUFFER_BINDING;
    const GLint saved = getInt(binding);
    if (GLuint(saved) != buffer) gRealGl.glBindBuffer(target, buffer);
    GLint size = 0;
    gRealGl.glGetBufferParameteriv(target, GL_BUFFER_SIZE, &size);
    if (GLuint(saved) != buffer) gRealGl.glBindBuffer(target, GLuint(saved));
    return size > 0 ? uint64_t(size) : 0;
}

void ReplaySink::addArray(GLint size, GLenum type, GLint stride, GLuint buffer, const void* pointer,
                          bool fixedSize, int count)
{
    ArrayUse use;
    use.element =
        fixedSize ? uint64_t(count) * arrayElementBytes(1, type) : arrayElementBytes(size, type);
    use.stride = stride > 0 ? uint64_t(stride) : use.element;
    if (buffer) {
        use.start = reinterpret_cast<uintptr_t>(pointer);
        use.bufferSize = bufferSize(GL_ARRAY_BUFFER, buffer);
    } else if (int slot = mArrays.slotOf(pointer); slot >= 0) {
        use.slot = slot;
        use.start = static_cast<const uint8_t*>(pointer) - mArrays.base(slot);
    }
    // An element size of 0 (a type this code does not know) counts as no data.
    if (!use.element) use = ArrayUse{};
    mUses.push_back(use);
}

bool ReplaySink::queryArrays()
{
    mUses.clear();
    struct Fixed {
        GLenum cap, size, type, stride, buffer, pointer;
        int count; // components when the array has no size query
    };
    static constexpr Fixed kFixed[] = {
        {GL_VERTEX_ARRAY, GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE, GL_VERTEX_ARRAY_STRIDE,
         GL_VERTEX_ARRAY_BUFFER_BINDING, GL_VERTEX_ARRAY_POINTER, 0},
        {GL_NORMAL_ARRAY, 0, GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE,
         GL_NORMAL_ARRAY_BUFFER_BINDING, GL_NORMAL_ARRAY_POINTER, 3},
        {GL_COLOR_ARRAY, GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE, GL_COLOR_ARRAY_STRIDE,
         GL_COLOR_ARRAY_BUFFER_BINDING, GL_COLOR_ARRAY_POINTER, 0},
        {GL_SECONDARY_COLOR_ARRAY, GL_SECONDARY_COLOR_ARRAY_SIZE, GL_SECONDARY_COLOR_ARRAY_TYPE,
         GL_SECONDARY_COLOR_ARRAY_STRIDE, GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING,
         GL_SECONDARY_COLOR_ARRAY_POINTER, 0},
        {GL_FOG_COORD_ARRAY, 0, GL_FOG_COORD_ARRAY_TYPE, GL_FOG_COORD_ARRAY_STRIDE,
         GL_FOG_COORD_ARRAY_BUFFER_BINDING, GL_FOG_COORD_ARRAY_POINTER, 1},
        {GL_INDEX_ARRAY, 0, GL_INDEX_ARRAY_TYPE, GL_INDEX_ARRAY_STRIDE,
         GL_INDEX_ARRAY_BUFFER_BINDING, GL_INDEX_ARRAY_POINTER, 1},
        {GL_EDGE_FLAG_ARRAY, 0, 0, GL_EDGE_FLAG_ARRAY_STRIDE, GL_EDGE_FLAG_ARRAY_BUFFER_BINDING,
         GL_EDGE_FLAG_ARRAY_POINTER, 1},
    };
    auto addFixed = [&](const Fixed& f) {
        if (!gRealGl.glIsEnabled(f.cap)) return;
        const GLenum type = f.type ? GLenum(getInt(f.type)) : GL_UNSIGNED_BYTE;
        void* pointer = nullptr;
        gRealGl.glGetPointerv(f.pointer, &pointer);
        addArray(f.size ? getInt(f.size) : f.count, type, getInt(f.stride),
                 GLuint(getInt(f.buffer)), pointer, f.size == 0, f.count);
    };
    for (const Fixed& f : kFixed)
        addFixed(f);
    const GLint units = std::clamp(getInt(GL_MAX_TEXTURE_COORDS), 1, 32);
    const GLint active = getInt(GL_CLIENT_ACTIVE_TEXTURE);
    for (GLint unit = 0; unit < units; ++unit) {
        gRealGl.glClientActiveTexture(GL_TEXTURE0 + unit);
        addFixed({GL_TEXTURE_COORD_ARRAY, GL_TEXTURE_COORD_ARRAY_SIZE, GL_TEXTURE_COORD_ARRAY_TYPE,
                  GL_TEXTURE_COORD_ARRAY_STRIDE, GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING,
                  GL_TEXTURE_COORD_ARRAY_POINTER, 0});
    }
    gRealGl.glClientActiveTexture(GLenum(active));
    const GLint attribs = std::clamp(getInt(GL_MAX_VERTEX_ATTRIBS), 0, 32);
    for (GLint i = 0; i < attribs; ++i) {
        GLint enabled = 0, size = 4, type = GL_FLOAT, stride = 0, buffer = 0;
        gRealGl.glGetVertexAttribiv(GLuint(i), GL_VERTEX_ATTRIB_ARRAY_ENABLED, &enabled);
        if (!enabled) continue;
        gRealGl.glGetVertexAttribiv(GLuint(i), GL_VERTEX_ATTRIB_ARRAY_SIZE, &size);
        gRealGl.glGetVertexAttribiv(GLuint(i), GL_VERTEX_ATTRIB_ARRAY_TYPE, &type);
        gRealGl.glGetVertexAttribiv(GLuint(i), GL_VERTEX_ATTRIB_ARRAY_STRIDE, &stride);
        gRealGl.glGetVertexAttribiv(GLuint(i), GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &buffer);
        void* pointer = nullptr;
        gRealGl.glGetVertexAttribPointerv(GLuint(i), GL_VERTEX_ATTRIB_ARRAY_POINTER, &pointer);
        addArray(size, GLenum(type), stride, GLuint(buffer), pointer, false, 0);
    }
    mUsesValid = true;
    return true;
}

uint64_t ReplaySink::readableVertices(bool reserved) const
{
    uint64_t n = kNoArrays;
    for (const ArrayUse& a : mUses) {
        uint64_t size =
            a.slot >= 0 ? (reserved ? ShadowArrays::kReserve : mArrays.size(a.slot)) : a.bufferSize;
        uint64_t count = size >= a.start && size - a.start >= a.element && a.element
                             ? (size - a.start - a.element) / a.stride + 1
                             : 0;
        n = std::min(n, count);
    }
    return n;
}

bool ReplaySink::checkVertices(const char* call, uint64_t lo, uint64_t hi, bool reserved)
{
    if (!mUsesValid) queryArrays();
    const uint64_t readable = readableVertices(reserved);
    if (hi > readable) {
        return refuse(std::string(call) + " reads vertices " + std::to_string(lo) + ".." +
                      std::to_string(hi - 1) + " of arrays holding " + std::to_string(readable));
    }
    return true;
}

bool ReplaySink::chargeWork(uint64_t work)
{
    mTotalWork = satAdd(mTotalWork, work);
    if (mLimits.totalWork && mTotalWork > mLimits.totalWork)
        return refuse("the replay's work exceeds its limit");
    return true;
}

bool ReplaySink::chargeBytes(uint64_t bytes)
{
    mTotalBytes = satAdd(mTotalBytes, bytes);
    if (mLimits.totalBytes && mTotalBytes > mLimits.totalBytes)
        return refuse("the replay's textures and buffers exceed their limit");
    return true;
}

bool ReplaySink::checkImage(uint16_t opcode, const Image& image, GLenum format, GLenum type,
                            GLsizei width, GLsizei height, GLsizei depth)
{
    if (!idle()) return true; // the driver refuses pixel calls between glBegin and glEnd
    const char* name = opcodeName(opcode);
    const bool texImage =
        opcode == op::glTexImage1D || opcode == op::glTexImage2D || opcode == op::glTexImage3D;
    if (width <= 0 || height <= 0 || depth <= 0) return true; // nothing to read or allocate
    if (texImage) {
        const uint64_t texels = uint64_t(width) * uint64_t(height) * uint64_t(depth);
        if (texels > mLimits.texels)
            return refuse(std::string(name) + " of " + std::to_string(texels) + " texels");
        if (!chargeBytes(texels * 16)) return false;
    }
    UnpackState unpack;
    unpack.alignment = getInt(GL_UNPACK_ALIGNMENT);
    unpack.rowLength = getInt(GL_UNPACK_ROW_LENGTH);
    unpack.imageHeight = getInt(GL_UNPACK_IMAGE_HEIGHT);
    unpack.skipPixels = getInt(GL_UNPACK_SKIP_PIXELS);
    unpack.skipRows = getInt(GL_UNPACK_SKIP_ROWS);
    unpack.skipImages = getInt(GL_UNPACK_SKIP_IMAGES);
    const uint64_t need = imageBytes(format, type, width, height, depth, unpack);
    const GLuint pbo = GLuint(getInt(GL_PIXEL_UNPACK_BUFFER_BINDING));
    switch (image.mode) {
    case Image::kNull:
        if (pbo || texImage) return true; // offset 0 (checked by the driver), or no data
        return refuse(std::string(name) + " without pixels");
    case Image::kBytes:
        if (pbo) return refuse(std::string(name) + " with pixels and a pixel-unpack buffer");
        if (!need) return refuse(std::string(name) + " with a pixel layout nprgl cannot size");
        if (need > image.size) {
            return refuse(std::string(name) + " reads " + std::to_string(need) +
                          " bytes of pixels from " + std::to_string(image.size));
        }
        return true;
    case Image::kOffset:
        if (!pbo) return refuse(std::string(name) + " with an offset and no pixel-unpack buffer");
        if (need && (image.offset > UINT64_MAX - need ||
                     image.offset + need > bufferSize(GL_PIXEL_UNPACK_BUFFER, pbo))) {
            return refuse(std::string(name) + " reads past its pixel-unpack buffer");
        }
        return true;
    }
    return true;
}

bool ReplaySink::checkUnpacked(uint16_t opcode, const Image& image, size_t size)
{
    if (!idle() || size == 0 || size > (size_t(1) << 48)) return true; // the driver refuses
    const std::string name = opcodeName(opcode);
    const GLuint pbo = GLuint(getInt(GL_PIXEL_UNPACK_BUFFER_BINDING));
    switch (image.mode) {
    case Image::kNull: return true; // no data, or offset 0 (checked by the driver)
    case Image::kBytes:
        if (pbo) return refuse(name + " with data and a pixel-unpack buffer");
        if (size > image.size) {
            return refuse(name + " reads " + std::to_string(size) + " bytes of data from " +
                          std::to_string(image.size));
        }
        return true;
    case Image::kOffset:
        if (!pbo) return refuse(name + " with an offset and no pixel-unpack buffer");
        if (image.offset > UINT64_MAX - size ||
            image.offset + size > bufferSize(GL_PIXEL_UNPACK_BUFFER, pbo)) {
            return refuse(name + " reads past its pixel-unpack buffer");
        }
        return true;
    }
    return true;
}

bool ReplaySink::check_glDrawArrays(GLenum, GLint first, GLsizei count)
{
    if (count <= 0 || !idle()) return true; // the driver refuses or draws nothing
    // Mesa does not check the sign of first: it reads the arrays before their start.
    if (first < 0)
        return refuse("glDrawArrays from " + std::to_string(first) + ": a negative first");
    if (uint64_t(count) > mLimits.drawVertices)
        return refuse("glDrawArrays of " + std::to_string(count) + " vertices");
    mWork = 1 + uint64_t(count);
    return chargeWork(mWork) &&
           checkVertices("glDrawArrays", uint64_t(first), uint64_t(first) + uint64_t(count));
}

bool ReplaySink::checkIndices(const char* call, GLsizei count, GLenum type, const Image& image,
                              const void* indices, uint64_t& maxIndex)
{
    const uint64_t width = indexBytes(type);
    const uint64_t bytes = uint64_t(count) * width;
    const GLuint buffer = GLuint(getInt(GL_ELEMENT_ARRAY_BUFFER_BINDING));
    const uint8_t* data = nullptr;
    switch (image.mode) {
    case Image::kNull:
    case Image::kOffset: {
        if (!buffer) return refuse(std::string(call) + " without indices");
        const uint64_t offset = image.mode == Image::kOffset ? image.offset : 0;
        if (offset > UINT64_MAX - bytes ||
            offset + bytes > bufferSize(GL_ELEMENT_ARRAY_BUFFER, buffer)) {
            return refuse(std::string(call) + " reads past its element buffer");
        }
        mIndices.resize(bytes);
        gRealGl.glGetBufferSubData(GL_ELEMENT_ARRAY_BUFFER, GLintptr(offset), GLsizeiptr(bytes),
                                   mIndices.data());
        data = mIndices.data();
        break;
    }
    case Image::kBytes:
        if (buffer) return refuse(std::string(call) + " with indices and an element buffer");
        if (bytes > image.size) {
            return refuse(std::string(call) + " reads " + std::to_string(bytes) +
                          " bytes of indices from " + std::to_string(image.size));
        }
        data = static_cast<const uint8_t*>(indices);
        break;
    }
    maxIndex = 0;
    for (uint64_t i = 0; i < uint64_t(count); ++i) {
        uint64_t index = width == 1   ? data[i]
                         : width == 2 ? reinterpret_cast<const uint16_t*>(data)[i]
                                      : reinterpret_cast<const uint32_t*>(data)[i];
        maxIndex = std::max(maxIndex, index);
    }
    return true;
}

bool ReplaySink::check_glDrawElements(GLenum, GLsizei count, GLenum type, const void* indices,
                                      const Image& image)
{
    if (count <= 0 || !indexBytes(type) || !idle()) return true;
    if (uint64_t(count) > mLimits.drawVertices)
        return refuse("glDrawElements of " + std::to_string(count) + " indices");
    mWork = 1 + uint64_t(count);
    if (!chargeWork(mWork)) return false;
    uint64_t maxIndex = 0;
    if (!checkIndices("glDrawElements", count, type, image, indices, maxIndex)) return false;
    return checkVertices("glDrawElements", 0, maxIndex + 1);
}

bool ReplaySink::check_glDrawRangeElements(GLenum, GLuint start, GLuint end, GLsizei count,
                                           GLenum type, const void* indices, const Image& image)
{
    if (count <= 0 || end < start || !indexBytes(type) || !idle()) return true;
    if (uint64_t(count) > mLimits.drawVertices)
        return refuse("glDrawRangeElements of " + std::to_string(count) + " indices");
    mWork = 1 + uint64_t(count);
    if (!chargeWork(mWork)) return false;
    uint64_t maxIndex = 0;
    if (!checkIndices("glDrawRangeElements", count, type, image, indices, maxIndex)) return false;
    if (!checkVertices("glDrawRangeElements", 0, maxIndex + 1)) return false;
    // The driver may read the whole declared range, which must not fault. A range past the
    // arrays whose indices all find data (trigger-rally gives `end` one past its last vertex;
    // GL does not check the hint, and the program draws fine) is drawn without the range.
    mDropRange = readableVertices(true) < uint64_t(end) + 1;
    if (mDropRange && !mDropRangeSaid) {
        mDropRangeSaid = true;
        NPRGL_INFO("glDrawRangeElements with a range past its arrays (end %u) but indices "
                   "within them: drawn as glDrawElements (the range is only a hint)",
                   end);
    }
    return true;
}

void ReplaySink::issue_glDrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count,
                                           GLenum type, const void* indices)
{
    if (std::exchange(mDropRange, false)) {
        gl().glDrawElements(mode, count, type, indices);
    } else {
        gl().glDrawRangeElements(mode, start, end, count, type, indices);
    }
}

bool ReplaySink::check_glMultiDrawArrays(GLenum, const GLint* first, const GLsizei* count,
                                         GLsizei drawcount)
{
    if (drawcount <= 0 || !idle()) return true;
    if (!first || !count) return refuse("glMultiDrawArrays without its firsts and counts");
    uint64_t total = 0, hi = 0;
    for (GLsizei i = 0; i < drawcount; ++i) {
        if (count[i] <= 0) continue;
        if (first[i] < 0) {
            return refuse("glMultiDrawArrays from " + std::to_string(first[i]) +
                          ": a negative first");
        }
        total += uint64_t(count[i]);
        hi = std::max(hi, uint64_t(first[i]) + uint64_t(count[i]));
    }
    if (total > mLimits.drawVertices)
        return refuse("glMultiDrawArrays of " + std::to_string(total) + " vertices");
    mWork = 1 + total;
    return chargeWork(mWork) && (hi == 0 || checkVertices("glMultiDrawArrays", 0, hi));
}

bool ReplaySink::check_glArrayElement(GLint i)
{
    // Mesa does not check the sign: it reads the enabled arrays before their start.
    if (i < 0) return refuse("glArrayElement(" + std::to_string(i) + "): a negative index");
    // Between glBegin and glEnd the driver answers no query: the arrays asked at glBegin
    // hold unless a call since may have changed them.
    if (!mUsesValid && idle()) queryArrays();
    if (!mUsesValid) return refuse("glArrayElement after its arrays changed inside glBegin");
    return checkVertices("glArrayElement", uint64_t(i), uint64_t(i) + 1);
}

bool ReplaySink::check_glNewList(GLuint list, GLenum mode)
{
    mLists.newList(list, mode);
    return true;
}

bool ReplaySink::check_glEndList()
{
    mLists.endList();
    return chargeWork(mLists.takeOverhead());
}

bool ReplaySink::check_glCallList(GLuint list)
{
    mLists.addCall(list);
    if (!mLists.executing()) return true;
    const uint64_t cost = mLists.cost(list);
    if (cost > mLimits.listWork)
        return refuse("glCallList(" + std::to_string(list) + ") would run " + std::to_string(cost) +
                      " calls and vertices");
    return chargeWork(cost) && chargeWork(mLists.takeOverhead());
}

bool ReplaySink::check_glCallLists(GLsizei n, GLenum, const uint8_t*)
{
    if (n <= 0) return true;
    mLists.addCalls(uint64_t(n));
    if (!mLists.executing()) return true;
    const uint64_t cost = mLists.costOfCalls(uint64_t(n));
    if (cost > mLimits.listWork)
        return refuse("glCallLists of " + std::to_string(n) + " lists could run " +
                      std::to_string(cost) + " calls and vertices");
    return chargeWork(cost) && chargeWork(mLists.takeOverhead());
}

bool ReplaySink::check_glListBase(GLuint)
{
    // The budget counts glCallLists in a list as calls of the costliest list whatever the
    // base, so the base itself needs no following.
    return true;
}

bool ReplaySink::check_glDeleteLists(GLuint list, GLsizei range)
{
    if (range > 0 && uint64_t(range) > mLimits.names)
        return refuse("glDeleteLists of " + std::to_string(range) + " lists");
    if (range > 0) mLists.deleteLists(list, uint64_t(range));
    return chargeWork(mLists.takeOverhead());
}

bool ReplaySink::check_glGenLists(GLsizei range)
{
    if (range > 0 && uint64_t(range) > mLimits.names)
        return refuse("glGenLists of " + std::to_string(range) + " lists");
    return true;
}

bool ReplaySink::checkNames(GLsizei n, const void*)
{
    if (n > 0 && uint64_t(n) > mLimits.names)
        return refuse(std::string(opcodeName(mOpcode)) + " of " + std::to_string(n) + " names");
    return true;
}

bool ReplaySink::check_glEvalMesh1(GLenum, GLint i1, GLint i2)
{
    if (i2 < i1) return true;
    const uint64_t points = uint64_t(int64_t(i2) - i1 + 1);
    if (points > mLimits.drawVertices)
        return refuse("glEvalMesh1 of " + std::to_string(points) + " points");
    mWork = 1 + points;
    return chargeWork(mWork);
}

bool ReplaySink::check_glEvalMesh2(GLenum, GLint i1, GLint i2, GLint j1, GLint j2)
{
    if (i2 < i1 || j2 < j1) return true;
    const uint64_t rows = uint64_t(int64_t(i2) - i1 + 1), cols = uint64_t(int64_t(j2) - j1 + 1);
    if (rows > mLimits.drawVertices || cols > mLimits.drawVertices ||
        rows * cols > mLimits.drawVertices) {
        return refuse("glEvalMesh2 of " + std::to_string(rows) + "x" + std::to_string(cols) +
                      " points");
    }
    mWork = 1 + rows * cols;
    return chargeWork(mWork);
}

bool ReplaySink::check_glBufferData(GLenum, GLsizeiptr size, const uint8_t*, GLenum)
{
    if (size <= 0) return true;
    if (uint64_t(size) > mLimits.bufferBytes)
        return refuse("glBufferData of " + std::to_string(size) + " bytes");
    return chargeBytes(uint64_t(size));
}

bool ReplaySink::check_glCopyTexImage1D(GLenum, GLint, GLenum, GLint, GLint, GLsizei width, GLint)
{
    return check_glCopyTexImage2D(0, 0, 0, 0, 0, width, 1, 0);
}

bool ReplaySink::check_glCopyTexImage2D(GLenum, GLint, GLenum, GLint, GLint, GLsizei width,
                                        GLsizei height, GLint)
{
    if (width <= 0 || height <= 0) return true;
    const uint64_t texels = uint64_t(width) * uint64_t(height);
    if (texels > mLimits.texels)
        return refuse(std::string(opcodeName(mOpcode)) + " of " + std::to_string(texels) +
                      " texels");
    return chargeBytes(texels * 16);
}

bool ReplaySink::scalesWindow(GLenum binding) const
{
    // glViewport and glScissor are refused between glBegin and glEnd; so is the query.
    return (mScaleX != 1.0 || mScaleY != 1.0) && idle() && getInt(binding) == 0;
}

void ReplaySink::scaleRect(GLint& x, GLint& y, GLsizei& width, GLsizei& height) const
{
    if (width < 0 || height < 0) return; // the driver's error, as recorded
    auto edge = [](GLint v, double s) {
        return GLint(std::clamp(std::lround(double(v) * s), -(1l << 30), 1l << 30));
    };
    const GLint x1 = edge(GLint(std::min<int64_t>(int64_t(x) + width, 1 << 30)), mScaleX);
    const GLint y1 = edge(GLint(std::min<int64_t>(int64_t(y) + height, 1 << 30)), mScaleY);
    x = edge(x, mScaleX);
    y = edge(y, mScaleY);
    width = std::max(0, x1 - x);
    height = std::max(0, y1 - y);
}

void ReplaySink::issue_glViewport(GLint x, GLint y, GLsizei width, GLsizei height)
{
    if (scalesWindow(GL_DRAW_FRAMEBUFFER_BINDING)) scaleRect(x, y, width, height);
    gl().glViewport(x, y, width, height);
}

void ReplaySink::issue_glClear(GLbitfield mask)
{
    gl().glClear(mask);
    // Asked as the program would ask (a style's own framebuffer is not the program's).
    if (!(mask & GL_COLOR_BUFFER_BIT) || !mLists.executing() || !idle()) return;
    GLint framebuffer = 0, box[4] = {0, 0, 0, 0};
    GLboolean writes[4] = {GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE};
    gl().glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    gl().glGetBooleanv(GL_COLOR_WRITEMASK, writes);
    if (framebuffer != 0 || !writes[0] || !writes[1] || !writes[2]) return;
    if (gl().glIsEnabled(GL_SCISSOR_TEST)) {
        gl().glGetIntegerv(GL_SCISSOR_BOX, box);
        if (box[0] > 0 || box[1] > 0 || box[0] + box[2] < mWindowWidth ||
            box[1] + box[3] < mWindowHeight)
            return;
    }
    GLfloat colour[4] = {0, 0, 0, 0};
    gl().glGetFloatv(GL_COLOR_CLEAR_VALUE, colour);
    // A normalised 8-bit buffer clamps and rounds to the nearest level (NaN: as 0); a driver
    // may round a half the other way (Mesa stores 0.3 as 76), one level: far below the ΔE*ab
    // of 3 within which compare takes a pixel for the clear colour.
    for (int c = 0; c < 3; ++c) {
        const float v = colour[c] > 0.0f ? std::min(colour[c], 1.0f) : 0.0f;
        mClear[c] = uint8_t(std::lround(v * 255.0f));
    }
    mCleared = true;
}

void ReplaySink::issue_glScissor(GLint x, GLint y, GLsizei width, GLsizei height)
{
    if (scalesWindow(GL_DRAW_FRAMEBUFFER_BINDING)) scaleRect(x, y, width, height);
    gl().glScissor(x, y, width, height);
}

void ReplaySink::issue_glCopyTexImage2D(GLenum target, GLint level, GLenum internalformat,
                                        GLint x, GLint y, GLsizei width, GLsizei height,
                                        GLint border)
{
    // The texture is made at the scaled size: sampled with the same coordinates, it holds
    // the same part of the (scaled) picture.
    if (scalesWindow(GL_READ_FRAMEBUFFER_BINDING)) scaleRect(x, y, width, height);
    gl().glCopyTexImage2D(target, level, internalformat, x, y, width, height, border);
}

void ReplaySink::issue_glCopyTexSubImage2D(GLenum target, GLint level, GLint xoffset,
                                           GLint yoffset, GLint x, GLint y, GLsizei width,
                                           GLsizei height)
{
    if (width <= 0 || height <= 0 || !scalesWindow(GL_READ_FRAMEBUFFER_BINDING)) {
        gl().glCopyTexSubImage2D(target, level, xoffset, yoffset, x, y, width, height);
        return;
    }
    // The texture keeps its size, so the scaled region is stretched back into it: first an
    // empty copy through the pipeline (the compositor draws what it holds, as for the copy),
    // then a blit from the window into the texture's level.
    gl().glCopyTexSubImage2D(target, level, xoffset, yoffset, x, y, 0, 0);
    const GlDispatch& real = gRealGl;
    GLenum binding = GL_TEXTURE_BINDING_2D;
    if (target == GL_TEXTURE_RECTANGLE) binding = GL_TEXTURE_BINDING_RECTANGLE;
    if (target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z)
        binding = GL_TEXTURE_BINDING_CUBE_MAP;
    const GLuint texture = GLuint(getInt(binding));
    const GLint drawn = getInt(GL_DRAW_FRAMEBUFFER_BINDING);
    if (!mCopyFramebuffer) real.glGenFramebuffers(1, &mCopyFramebuffer);
    real.glBindFramebuffer(GL_DRAW_FRAMEBUFFER, mCopyFramebuffer);
    real.glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target, texture, level);
    GLint source[4] = {x, y, width, height};
    scaleRect(source[0], source[1], source[2], source[3]);
    const bool complete =
        real.glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
    if (complete) {
        const bool scissored = real.glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE; // blits are cut
        if (scissored) real.glDisable(GL_SCISSOR_TEST);
        real.glBlitFramebuffer(source[0], source[1], source[0] + source[2], source[1] + source[3],
                               xoffset, yoffset, xoffset + width, yoffset + height,
                               GL_COLOR_BUFFER_BIT, GL_LINEAR);
        if (scissored) real.glEnable(GL_SCISSOR_TEST);
    }
    real.glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, target, 0, level);
    real.glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawn));
    // A texture that cannot be drawn into (its format): the scaled region, unstretched.
    if (!complete) {
        real.glCopyTexSubImage2D(target, level, xoffset, yoffset, source[0], source[1],
                                 source[2], source[3]);
    }
}

void ReplaySink::issue_glBlitFramebuffer(GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1,
                                         GLint dstX0, GLint dstY0, GLint dstX1, GLint dstY1,
                                         GLbitfield mask, GLenum filter)
{
    auto scale = [](GLint& v, double s) {
        v = GLint(std::clamp(std::lround(double(v) * s), -(1l << 30), 1l << 30));
    };
    const bool source = scalesWindow(GL_READ_FRAMEBUFFER_BINDING);
    const bool target = scalesWindow(GL_DRAW_FRAMEBUFFER_BINDING);
    if (source) {
        for (GLint* v : {&srcX0, &srcX1}) scale(*v, mScaleX);
        for (GLint* v : {&srcY0, &srcY1}) scale(*v, mScaleY);
    }
    if (target) {
        for (GLint* v : {&dstX0, &dstX1}) scale(*v, mScaleX);
        for (GLint* v : {&dstY0, &dstY1}) scale(*v, mScaleY);
    }
    if (source != target) {
        // Now a resize: depth and stencil cannot be resized (the driver refuses the blit).
        mask &= GL_COLOR_BUFFER_BIT;
        filter = GL_LINEAR;
        if (!mask) return;
    }
    gl().glBlitFramebuffer(srcX0, srcY0, srcX1, srcY1, dstX0, dstY0, dstX1, dstY1, mask, filter);
}

} // namespace nprgl
