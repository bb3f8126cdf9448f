#include "frame/FrameReplay.h"

#include "frame/SavedGlState.h"
#include "frame/ShadowArrays.h"
#include "shim/RealGl.h"
#include "stream/CallDecoder.h"
#include "stream/Opcodes.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace nprgl {

namespace {

// Calls that cannot run a second time in place: they hand the driver memory of the program's
// to write later (selection and feedback buffers), map buffers the program writes through,
// or wait on objects of the frame's.
bool unsafeInPlace(const char* name)
{
    static constexpr const char* kPrefixes[] = {"glRenderMode", "glSelectBuffer",
                                                "glFeedbackBuffer", "glMap", "glUnmap",
                                                "glFenceSync", "glClientWaitSync", "glWaitSync",
                                                "glInterleavedArrays"};
    for (const char* p : kPrefixes) {
        if (std::strncmp(name, p, std::strlen(p)) == 0) return true;
    }
    return false;
}

// A decodeCall sink that runs nothing: finds a call that cannot run twice in place, and
// whether the frame pops what an earlier frame pushed (an attribute or matrix stack entry).
class Scan {
public:
    static constexpr bool kReplays = false;
    const char* unsafe = nullptr;
    bool popsEarlier = false;

    void begin(const char* name)
    {
        if (!unsafe && unsafeInPlace(name)) unsafe = name;
        mCall = name;
        auto push = [&](int& depth, int by) {
            depth += by;
            if (depth < 0) popsEarlier = true;
        };
        if (mCall == "glPushAttrib") push(mAttrib, 1);
        else if (mCall == "glPopAttrib") push(mAttrib, -1);
        else if (mCall == "glPushClientAttrib") push(mClient, 1);
        else if (mCall == "glPopClientAttrib") push(mClient, -1);
        else if (mCall == "glPushMatrix") push(mMatrices[stack()], 1);
        else if (mCall == "glPopMatrix") push(mMatrices[stack()], -1);
    }
    void arg(const char*, double) {}
    void argEnum(const char*, uint32_t value, int)
    {
        if (mCall == "glMatrixMode") mMode = value;
        if (mCall == "glActiveTexture") mUnit = value;
    }
    void argBits(const char*, uint32_t, int) {}
    template <typename T>
    void argArray(const char*, const T*, size_t)
    {
    }
    void argBlob(const char*, const void*) {}
    void argString(const char*, const char*) {}
    void argSources(const char*, const CallReader::Sources&) {}
    void argPointer(const char*, uint64_t) {}
    void end() {}
    template <typename T>
    T* scratch(size_t)
    {
        return nullptr;
    }
    bool pseudo(CallReader& r, uint16_t opcode) { return skipPseudo(r, opcode); }

private:
    // The matrix stack glPushMatrix and glPopMatrix work on now.
    uint64_t stack() const
    {
        return mMode == GL_TEXTURE ? (uint64_t(mMode) << 32 | mUnit) : uint64_t(mMode) << 32;
    }

    std::string mCall;
    int mAttrib = 0, mClient = 0;
    std::map<uint64_t, int> mMatrices;
    uint32_t mMode = GL_MODELVIEW, mUnit = GL_TEXTURE0;

public:

    static bool skipPseudo(CallReader& r, uint16_t opcode)
    {
        switch (opcode) {
        case op::kFrameEnd:
            r.get<uint64_t>();
            return r.ok();
        case op::kArrayData:
            return CallReader::Payload(r).skip();
        case op::kUncaptured: {
            CallReader::Uncaptured ignored;
            return r.getUncaptured(ignored);
        }
        case op::kCreated: // in the program's own process its names are the driver's
            r.get<uint32_t>();
            return r.ok();
        default:
            r.fail("a pseudo-call a kept frame does not hold (opcode " + std::to_string(opcode) +
                   ")");
            return false;
        }
    }
};

// Calls that make names: the program has them already (the frame's calls use the names its
// own calls got), so these run as nothing.
void APIENTRY noNames(GLsizei, GLuint*) {}
void APIENTRY noTypedNames(GLenum, GLsizei, GLuint*) {}
GLuint APIENTRY noList(GLsizei) { return 0; }
GLuint APIENTRY noProgram() { return 0; }
GLuint APIENTRY noShader(GLenum) { return 0; }

// The stacks' pushes of the replay not yet popped. A frame may pop what an earlier frame
// pushed: that entry is the program's, under nprgl's own saved state, so such a pop runs as
// nothing; and whatever the replay left pushed is popped before the state goes back.
struct Pushes {
    int attrib = 0, client = 0;
    std::array<int, 4 + 8> matrices{}; // modelview, projection, colour, texture of units 0-7
    GLenum mode = GL_MODELVIEW;
    int unit = 0; // the active texture unit (its matrix stack is GL_TEXTURE's)

    int* matrix()
    {
        switch (mode) {
        case GL_MODELVIEW: return &matrices[0];
        case GL_PROJECTION: return &matrices[1];
        case GL_COLOR: return &matrices[2];
        case GL_TEXTURE: return unit >= 0 && unit < 8 ? &matrices[size_t(4 + unit)] : nullptr;
        default: return nullptr;
        }
    }
};
thread_local Pushes tPushes;

bool room(GLenum depth, GLenum max)
{
    GLint d = 0, m = 0;
    gRealGl.glGetIntegerv(depth, &d);
    gRealGl.glGetIntegerv(max, &m);
    return d < m;
}
void APIENTRY pushAttrib(GLbitfield mask)
{
    if (!room(GL_ATTRIB_STACK_DEPTH, GL_MAX_ATTRIB_STACK_DEPTH)) return;
    ++tPushes.attrib;
    gRealGl.glPushAttrib(mask);
}
void APIENTRY popAttrib()
{
    if (tPushes.attrib == 0) return;
    --tPushes.attrib;
    gRealGl.glPopAttrib();
}
void APIENTRY pushClientAttrib(GLbitfield mask)
{
    if (!room(GL_CLIENT_ATTRIB_STACK_DEPTH, GL_MAX_CLIENT_ATTRIB_STACK_DEPTH)) return;
    ++tPushes.client;
    gRealGl.glPushClientAttrib(mask);
}
void APIENTRY popClientAttrib()
{
    if (tPushes.client == 0) return;
    --tPushes.client;
    gRealGl.glPopClientAttrib();
}
void APIENTRY matrixMode(GLenum mode)
{
    tPushes.mode = mode;
    gRealGl.glMatrixMode(mode);
}
void APIENTRY activeTexture(GLenum unit)
{
    tPushes.unit = int(unit) - GL_TEXTURE0;
    gRealGl.glActiveTexture(unit);
}
void APIENTRY pushMatrix()
{
    int* pushed = tPushes.matrix();
    if (!pushed) return;
    GLint depth = 0, max = 0;
    const GLenum mode = tPushes.mode;
    gRealGl.glGetIntegerv(mode == GL_MODELVIEW    ? GL_MODELVIEW_STACK_DEPTH
                          : mode == GL_PROJECTION ? GL_PROJECTION_STACK_DEPTH
                          : mode == GL_COLOR      ? GL_COLOR_MATRIX_STACK_DEPTH
                                                  : GL_TEXTURE_STACK_DEPTH,
                          &depth);
    gRealGl.glGetIntegerv(mode == GL_MODELVIEW    ? GL_MAX_MODELVIEW_STACK_DEPTH
                          : mode == GL_PROJECTION ? GL_MAX_PROJECTION_STACK_DEPTH
                          : mode == GL_COLOR      ? GL_MAX_COLOR_MATRIX_STACK_DEPTH
                                                  : GL_MAX_TEXTURE_STACK_DEPTH,
                          &max);
    if (depth >= max) return;
    ++*pushed;
    gRealGl.glPushMatrix();
}
void APIENTRY popMatrix()
{
    int* pushed = tPushes.matrix();
    if (!pushed || *pushed == 0) return;
    --*pushed;
    gRealGl.glPopMatrix();
}

// Pops what the replay pushed and did not pop.
void popReplayPushes()
{
    const GlDispatch& gl = gRealGl;
    Pushes& p = tPushes;
    for (; p.attrib > 0; --p.attrib) gl.glPopAttrib();
    for (; p.client > 0; --p.client) gl.glPopClientAttrib();
    const GLenum modes[3] = {GL_MODELVIEW, GL_PROJECTION, GL_COLOR};
    for (size_t i = 0; i < p.matrices.size(); ++i) {
        if (p.matrices[i] == 0) continue;
        if (i < 3) {
            gl.glMatrixMode(modes[i]);
        } else {
            gl.glMatrixMode(GL_TEXTURE);
            gl.glActiveTexture(GLenum(GL_TEXTURE0 + i - 4));
        }
        for (; p.matrices[i] > 0; --p.matrices[i]) gl.glPopMatrix();
    }
}

// The decodeCall sink: the driver's entry points (those making names excepted), client arrays
// from the frame's own copies.
class InPlace {
public:
    static constexpr bool kReplays = true;

    // guardStacks: pops below the replay's own pushes run as nothing (see Pushes).
    InPlace(ShadowArrays& arrays, bool guardStacks) : mArrays(arrays), mGl(gRealGl)
    {
        // (The ARB and EXT spellings of core entry points share their core slot.)
        for (auto* slot : {&mGl.glGenTextures, &mGl.glGenTexturesEXT, &mGl.glGenBuffers,
                           &mGl.glGenFramebuffers, &mGl.glGenRenderbuffers, &mGl.glGenQueries,
                           &mGl.glGenVertexArrays, &mGl.glGenProgramsARB, &mGl.glGenSamplers,
                           &mGl.glGenTransformFeedbacks, &mGl.glGenProgramPipelines,
                           &mGl.glCreateBuffers, &mGl.glCreateFramebuffers,
                           &mGl.glCreateRenderbuffers, &mGl.glCreateSamplers,
                           &mGl.glCreateVertexArrays, &mGl.glCreateProgramPipelines,
                           &mGl.glCreateTransformFeedbacks}) {
            *slot = &noNames;
        }
        mGl.glCreateTextures = &noTypedNames;
        mGl.glCreateQueries = &noTypedNames;
        mGl.glGenLists = &noList;
        if (guardStacks) {
            mGl.glPushAttrib = &pushAttrib;
            mGl.glPopAttrib = &popAttrib;
            mGl.glPushClientAttrib = &pushClientAttrib;
            mGl.glPopClientAttrib = &popClientAttrib;
            mGl.glMatrixMode = &matrixMode;
            mGl.glActiveTexture = &activeTexture;
            mGl.glPushMatrix = &pushMatrix;
            mGl.glPopMatrix = &popMatrix;
        }
        mGl.glCreateProgram = &noProgram;
        mGl.glCreateShader = &noShader;
    }

    const GlDispatch& gl() const { return mGl; }
    bool before(uint16_t opcode)
    {
        mOpcode = opcode;
        return true;
    }
    void after(uint16_t opcode)
    {
        // (glPopClientAttrib puts back the unit that was active at its push.)
        if (opcode == op::glClientActiveTexture || opcode == op::glPopClientAttrib) {
            GLint unit = GL_TEXTURE0;
            gRealGl.glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &unit);
            mClientActiveTexture = unit - GL_TEXTURE0;
        }
    }
    template <typename T>
    T* scratch(size_t n)
    {
        mScratch.assign((n + 1) * sizeof(T), 0);
        return reinterpret_cast<T*>(mScratch.data());
    }
    // A client-array pointer: an offset where a buffer is bound, else the slot's copy (the
    // recorder sends a draw's data as offsets from the pointer).
    const void* clientPointer(uint64_t value, int attribIndex)
    {
        GLint buffer = 0;
        gRealGl.glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &buffer);
        if (buffer) return reinterpret_cast<const void*>(uintptr_t(value));
        const int slot = arraySlotForPointerCall(mOpcode, attribIndex, mClientActiveTexture);
        return slot >= 0 ? mArrays.base(slot) : nullptr;
    }
    bool pseudo(CallReader& r, uint16_t opcode)
    {
        if (opcode == op::kArrayData) return mArrays.apply(r);
        return Scan::skipPseudo(r, opcode);
    }

private:
    ShadowArrays& mArrays;
    GlDispatch mGl;
    uint16_t mOpcode = 0;
    int mClientActiveTexture = 0;
    std::vector<uint8_t> mScratch;
};

// Points the client arrays of `state` that are in client memory at where(slot), laid out as
// `state` has them (null: left as they are).
template <typename Where>
void pointArrays(const ClientArrayState& state, Where&& where)
{
    const GlDispatch& gl = gRealGl;
    gl.glBindBuffer(GL_ARRAY_BUFFER, 0);
    GLint clientUnit = GL_TEXTURE0;
    gl.glGetIntegerv(GL_CLIENT_ACTIVE_TEXTURE, &clientUnit);
    for (int slot = 0; slot < kArraySlotCount; ++slot) {
        const ClientArray& a = state.arrays[size_t(slot)];
        if (a.inBuffer || !a.pointer) continue;
        const void* p = where(slot, a);
        if (!p) continue;
        switch (slot) {
        case kVertexArray: gl.glVertexPointer(a.size, a.type, a.stride, p); break;
        case kNormalArray: gl.glNormalPointer(a.type, a.stride, p); break;
        case kColorArray: gl.glColorPointer(a.size, a.type, a.stride, p); break;
        case kSecondaryColorArray:
            if (gl.glSecondaryColorPointer) gl.glSecondaryColorPointer(a.size, a.type, a.stride, p);
            break;
        case kFogCoordArray:
            if (gl.glFogCoordPointer) gl.glFogCoordPointer(a.type, a.stride, p);
            break;
        case kIndexArray: gl.glIndexPointer(a.type, a.stride, p); break;
        case kEdgeFlagArray: gl.glEdgeFlagPointer(a.stride, p); break;
        default:
            if (slot < kAttribArray0) {
                gl.glClientActiveTexture(GLenum(GL_TEXTURE0 + slot - kTexCoordArray0));
                gl.glTexCoordPointer(a.size, a.type, a.stride, p);
            } else if (gl.glVertexAttribPointer && gl.glGetVertexAttribiv) {
                const GLuint index = GLuint(slot - kAttribArray0);
                GLint normalized = GL_FALSE;
                gl.glGetVertexAttribiv(index, GL_VERTEX_ATTRIB_ARRAY_NORMALIZED, &normalized);
                gl.glVertexAttribPointer(index, a.size, a.type, GLboolean(normalized), a.stride, p);
            }
            break;
        }
    }
    gl.glClientActiveTexture(GLenum(clientUnit));
}

// The tops of the matrix stacks (glPushAttrib keeps none of them) and the matrix mode.
class Matrices {
public:
    void save()
    {
        const GlDispatch& gl = gRealGl;
        gl.glGetIntegerv(GL_MATRIX_MODE, &mMode);
        gl.glGetIntegerv(GL_ACTIVE_TEXTURE, &mUnit);
        gl.glGetFloatv(GL_MODELVIEW_MATRIX, mModelview.data());
        gl.glGetFloatv(GL_PROJECTION_MATRIX, mProjection.data());
        GLint units = 0;
        gl.glGetIntegerv(GL_MAX_TEXTURE_COORDS, &units);
        mTexture.resize(size_t(std::clamp(units, 1, 8)));
        for (size_t u = 0; u < mTexture.size(); ++u) {
            gl.glActiveTexture(GLenum(GL_TEXTURE0 + u));
            gl.glGetFloatv(GL_TEXTURE_MATRIX, mTexture[u].data());
        }
        gl.glActiveTexture(GLenum(mUnit));
    }
    void restore() const
    {
        const GlDispatch& gl = gRealGl;
        gl.glMatrixMode(GL_MODELVIEW);
        gl.glLoadMatrixf(mModelview.data());
        gl.glMatrixMode(GL_PROJECTION);
        gl.glLoadMatrixf(mProjection.data());
        gl.glMatrixMode(GL_TEXTURE);
        for (size_t u = 0; u < mTexture.size(); ++u) {
            gl.glActiveTexture(GLenum(GL_TEXTURE0 + u));
            gl.glLoadMatrixf(mTexture[u].data());
        }
        gl.glActiveTexture(GLenum(mUnit));
        gl.glMatrixMode(GLenum(mMode));
    }

private:
    GLint mMode = GL_MODELVIEW, mUnit = GL_TEXTURE0;
    std::array<float, 16> mModelview{}, mProjection{};
    std::vector<std::array<float, 16>> mTexture;
};

} // namespace

bool FrameReplay::run(const uint8_t* data, size_t size, const ClientArrayState& start,
                      const ClientArrayState& end, std::string& error)
{
    Scan scan;
    {
        CallReader r(data, size, nullptr);
        if (!decodeCalls(r, scan)) {
            error = "its calls cannot be read again: " + r.error();
            return false;
        }
        if (scan.unsafe) {
            error = std::string("it calls ") + scan.unsafe + ", which cannot run twice in place";
            return false;
        }
    }
    // A frame that keeps to its own stack entries runs between nprgl's saved state and its
    // restoring. One that pops an earlier frame's entry (and pushes one for the next) needs
    // that entry on top: it runs from the state it left, which it leaves again as it was
    // (a program draws every frame from the state the last one left); only the client arrays
    // pointed at the copies are pointed back.
    const bool guarded = !scan.popsEarlier;
    SavedGlState saved;
    Matrices matrices;
    if (guarded) {
        if (!saved.resolve() || !saved.save(false)) {
            error = "the attribute stacks are full";
            return false;
        }
        matrices.save();
    }
    ShadowArrays arrays;
    pointArrays(start, [&](int slot, const ClientArray& a) -> const void* {
        return a.enabled ? arrays.base(slot) : nullptr;
    });
    tPushes = Pushes();
    gRealGl.glGetIntegerv(GL_MATRIX_MODE, reinterpret_cast<GLint*>(&tPushes.mode));
    GLint unit = GL_TEXTURE0;
    gRealGl.glGetIntegerv(GL_ACTIVE_TEXTURE, &unit);
    tPushes.unit = unit - GL_TEXTURE0;
    InPlace sink(arrays, guarded);
    CallReader r(data, size, nullptr);
    const bool ok = decodeCalls(r, sink);
    if (guarded) {
        popReplayPushes();
        matrices.restore();
        saved.restore();
    } else {
        pointArrays(end, [](int, const ClientArray& a) -> const void* { return a.pointer; });
        gRealGl.glBindBuffer(GL_ARRAY_BUFFER, end.arrayBuffer);
    }
    if (!ok) error = "a call could not be run again: " + r.error();
    return ok;
}

} // namespace nprgl
