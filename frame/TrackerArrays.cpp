// Client arrays, buffer objects and the draws that read them (varray.c's part of the tracker).
#include "frame/StateTracker.h"

#include "frame/TrackerGl.h"

#include "stream/GlSizes.h"
#include "stream/Opcodes.h"

#include <algorithm>
#include <cstring>

namespace nprgl {

using namespace tracker;

namespace {

// Component i of an array element (unaligned).
template <typename T>
T load(const uint8_t* p, int i)
{
    T v;
    std::memcpy(&v, p + sizeof(T) * size_t(i), sizeof(T));
    return v;
}

} // namespace

const void* StateTracker::clientPointer(uint64_t value, int attribIndex)
{
    if (mArrayBuffer) return reinterpret_cast<const void*>(uintptr_t(value));
    if (attribIndex >= 0) return nullptr; // generic attributes are not followed
    switch (mOpcode) {
    case op::glVertexPointer: return mArrays.base(kVertexArray);
    case op::glNormalPointer: return mArrays.base(kNormalArray);
    case op::glColorPointer: return mArrays.base(kColorArray);
    case op::glTexCoordPointer: return mArrays.base(texCoordSlot());
    default: return nullptr;
    }
}

void StateTracker::enableArray(GLenum cap, bool on)
{
    int slot = arraySlotForCap(cap, mClientActiveTexture);
    if (slot >= 0) mArrayState[slot].array.enabled = on;
}

void StateTracker::clientActiveTexture(GLenum unit)
{
    if (unit >= GL_TEXTURE0 && unit < GL_TEXTURE0 + 8)
        mClientActiveTexture = int(unit - GL_TEXTURE0);
}

void StateTracker::arrayPointer(int slot, GLint size, GLenum type, GLsizei stride,
                                const void* pointer)
{
    ArrayBinding& b = mArrayState[slot];
    b.array.size = size;
    b.array.type = type;
    b.array.stride = stride;
    b.array.pointer = static_cast<const uint8_t*>(pointer);
    b.buffer = mArrayBuffer;
    b.array.inBuffer = mArrayBuffer != 0;
}

void StateTracker::pushClientAttrib()
{
    mClientDepth += mClientDepth < 64;
    ClientState saved;
    std::copy(std::begin(mArrayState), std::end(mArrayState), saved.arrays.begin());
    saved.clientActiveTexture = mClientActiveTexture;
    saved.arrayBuffer = mArrayBuffer;
    saved.elementBuffer = mElementBuffer;
    mClientStack.push_back(saved);
}

void StateTracker::popClientAttrib()
{
    mClientDepth -= mClientDepth > 0;
    if (mClientStack.empty()) return;
    const ClientState& saved = mClientStack.back();
    std::copy(saved.arrays.begin(), saved.arrays.end(), std::begin(mArrayState));
    mClientActiveTexture = saved.clientActiveTexture;
    mArrayBuffer = saved.arrayBuffer;
    mElementBuffer = saved.elementBuffer;
    mClientStack.pop_back();
}

void StateTracker::bindBuffer(GLenum target, GLuint buffer)
{
    if (target == GL_ARRAY_BUFFER) mArrayBuffer = buffer;
    if (target == GL_ELEMENT_ARRAY_BUFFER) mElementBuffer = buffer;
}

void StateTracker::bufferData(GLenum target, GLsizeiptr size, const void* data)
{
    GLuint id = target == GL_ARRAY_BUFFER ? mArrayBuffer
                : target == GL_ELEMENT_ARRAY_BUFFER ? mElementBuffer
                                                    : 0;
    if (!id || size < 0 || size > (GLsizeiptr(1) << 31)) return;
    auto& bytes = mBuffers[id];
    bytes.assign(size_t(size), 0);
    if (data) std::memcpy(bytes.data(), data, size_t(size));
}

void StateTracker::bufferSubData(GLenum target, GLintptr offset, GLsizeiptr size,
                                 const void* data)
{
    GLuint id = target == GL_ARRAY_BUFFER ? mArrayBuffer
                : target == GL_ELEMENT_ARRAY_BUFFER ? mElementBuffer
                                                    : 0;
    auto it = mBuffers.find(id);
    if (it == mBuffers.end() || !data || offset < 0 || size < 0 ||
        size_t(offset) + size_t(size) > it->second.size()) {
        return;
    }
    std::memcpy(it->second.data() + offset, data, size_t(size));
}

StateTracker::ArraySource StateTracker::source(int slot) const
{
    ArraySource s;
    const ArrayBinding& b = mArrayState[slot];
    const ClientArray& a = b.array;
    s.elem = a.elementBytes();
    s.stride = a.effectiveStride();
    if (!a.enabled || !s.elem) return s;
    if (a.inBuffer) {
        auto it = mBuffers.find(b.buffer);
        const size_t offset = reinterpret_cast<uintptr_t>(a.pointer);
        if (it == mBuffers.end() || offset > it->second.size()) return s;
        s.base = it->second.data() + offset;
        s.limit = it->second.size() - offset;
    } else {
        if (!a.pointer) return s;
        s.base = a.pointer;
        s.limit = ShadowArrays::kReserve;
    }
    s.type = a.type;
    s.count = std::min(a.size == GL_BGRA ? 4 : a.size, 4);
    s.normalize = slot == kColorArray || slot == kNormalArray;
    s.bgra = a.size == GL_BGRA;
    return s;
}

StateTracker::DrawSources StateTracker::drawSources()
{
    followSurfaceUnit();
    return {source(kVertexArray), source(kNormalArray), source(kColorArray),
            source(kTexCoordArray0 + mSurfaceUnit),
            mLightUnit >= 0 ? source(kTexCoordArray0 + mLightUnit) : ArraySource{}};
}

bool StateTracker::fetch(const ArraySource& from, size_t index, float out[4])
{
    if (!from.base || index * from.stride + from.elem > from.limit) return false;
    const uint8_t* p = from.base + index * from.stride;
    const bool normalize = from.normalize;
    const int n = from.count;
    if (from.type == GL_FLOAT) {
        std::memcpy(out, p, size_t(n) * sizeof(float)); // the common case, no conversion
    } else {
        for (int i = 0; i < n; ++i) {
            double v = 0;
            switch (from.type) {
            case GL_DOUBLE: v = load<double>(p, i); break;
            case GL_INT: v = load<int32_t>(p, i) / (normalize ? 2147483647.0 : 1.0); break;
            case GL_UNSIGNED_INT:
                v = load<uint32_t>(p, i) / (normalize ? 4294967295.0 : 1.0);
                break;
            case GL_SHORT: v = load<int16_t>(p, i) / (normalize ? 32767.0 : 1.0); break;
            case GL_UNSIGNED_SHORT: v = load<uint16_t>(p, i) / (normalize ? 65535.0 : 1.0); break;
            case GL_BYTE: v = load<int8_t>(p, i) / (normalize ? 127.0 : 1.0); break;
            case GL_UNSIGNED_BYTE: v = load<uint8_t>(p, i) / (normalize ? 255.0 : 1.0); break;
            default: return false;
            }
            out[i] = float(v);
        }
    }
    if (from.bgra) std::swap(out[0], out[2]);
    return true;
}

TrackedVertex StateTracker::arrayVertex(const DrawSources& from, size_t index,
                                        bool hasNormal) const
{
    TrackedVertex v = mCurrent;
    v.hasNormal = hasNormal;
    float f[4] = {0, 0, 0, 1};
    if (fetch(from.vertex, index, f)) {
        v.position = f[3] != 0.0f && f[3] != 1.0f ? glm::vec3(f[0], f[1], f[2]) / f[3]
                                                  : glm::vec3(f[0], f[1], f[2]);
    }
    float n[4] = {0, 0, 1, 0};
    if (fetch(from.normal, index, n)) v.normal = {n[0], n[1], n[2]};
    float c[4] = {1, 1, 1, 1};
    if (fetch(from.color, index, c)) v.color = {c[0], c[1], c[2], c[3]};
    float t[4] = {0, 0, 0, 1};
    if (fetch(from.texcoord, index, t)) v.texcoord = {t[0], t[1]};
    float l[4] = {0, 0, 0, 1};
    if (fetch(from.lightcoord, index, l)) v.lightcoord = {l[0], l[1]};
    return v;
}

void StateTracker::noteListArrays()
{
    // A list compiled from arrays holds the arrays' normals, colours and texcoords as they
    // were: a call of it must not take the caller's current ones instead.
    if (!mCompiling) return;
    mListSetsNormal = mListSetsNormal || mArrayState[kNormalArray].array.enabled;
    mListSetsColor = mListSetsColor || mArrayState[kColorArray].array.enabled;
    mListSetsTexCoord = mListSetsTexCoord || mArrayState[kTexCoordArray0].array.enabled;
}

void StateTracker::drawArrays(GLenum mode, GLint first, GLsizei count)
{
    if (first < 0 || count <= 0 || !mArrayState[kVertexArray].array.enabled) return;
    TrackedBatch batch;
    batch.mode = mode;
    batch.hasNormals = currentNormalCounts() || mArrayState[kNormalArray].array.enabled;
    batch.vertices = takeVertices();
    batch.vertices.reserve(size_t(count));
    const DrawSources from = drawSources();
    for (GLsizei i = 0; i < count; ++i) {
        batch.vertices.push_back(arrayVertex(from, size_t(first + i), batch.hasNormals));
    }
    noteListArrays();
    emit(std::move(batch));
}

void StateTracker::drawElements(GLenum mode, GLsizei count, GLenum type, const void* indices)
{
    const size_t width = indexBytes(type);
    if (count <= 0 || !width || !mArrayState[kVertexArray].array.enabled) return;
    const uint8_t* data = static_cast<const uint8_t*>(indices);
    if (mElementBuffer) {
        auto it = mBuffers.find(mElementBuffer);
        size_t offset = reinterpret_cast<uintptr_t>(indices);
        if (it == mBuffers.end() || offset + size_t(count) * width > it->second.size()) return;
        data = it->second.data() + offset;
    }
    if (!data) return;
    TrackedBatch batch;
    batch.mode = mode;
    batch.quadCut = reconstruct::QuadCut::V1V3; // indexed (reconstruct::QuadCut)
    batch.hasNormals = currentNormalCounts() || mArrayState[kNormalArray].array.enabled;
    batch.vertices = takeVertices();
    batch.vertices.reserve(size_t(count));
    const DrawSources from = drawSources();
    for (GLsizei i = 0; i < count; ++i) {
        uint32_t index = 0;
        std::memcpy(&index, data + size_t(i) * width, width); // little-endian
        batch.vertices.push_back(arrayVertex(from, index, batch.hasNormals));
    }
    noteListArrays();
    emit(std::move(batch));
}

void StateTracker::arrayElement(GLint i)
{
    if (!mInBegin || i < 0) return;
    // A normal array gives this batch its normals (see end()).
    if (mArrayState[kNormalArray].array.enabled) mNormalFresh = true;
    mBatch.vertices.push_back(arrayVertex(drawSources(), size_t(i), mCurrent.hasNormal));
    noteListArrays();
}

void StateTracker::rect(float x1, float y1, float x2, float y2)
{
    TrackedBatch batch;
    batch.mode = GL_POLYGON;
    for (auto [x, y] : {std::pair{x1, y1}, {x2, y1}, {x2, y2}, {x1, y2}}) {
        TrackedVertex v = mCurrent;
        v.position = {x, y, 0.0f};
        v.hasNormal = false; // as the batch's hasNormals
        batch.vertices.push_back(v);
    }
    emit(std::move(batch));
}

} // namespace nprgl
