#pragma once

// ReplaySink: the decodeCall sink that replays a stream through the current context's
// dispatch, refusing calls the driver would trust and crash or hang on.

#include "replay/DisplayListBudget.h"
#include "frame/ShadowArrays.h"
#include "replay/ReplayLimits.h"
#include "shim/Api.h"
#include "shim/ThreadState.h"
#include "stream/CallReader.h"

#include <algorithm>
#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

namespace nprgl {

// Drivers trust what a program hands them: a draw's count against the arrays it reads, a
// pointer that is an offset, a list that calls lists. A capture is untrusted, so before such
// a call reaches the driver the sink checks it against the state it reads (queried from the
// driver, and the shadow arrays' sizes) and refuses it with a message (error()).
class ReplaySink {
public:
    static constexpr bool kReplays = true;
    using Image = CallReader::Image;

    ReplaySink(ShadowArrays& arrays, const ReplayLimits& limits,
               std::function<bool(uint64_t)> frameEnd);

    const GlDispatch& gl() const { return *tThread.dispatch; }
    bool before(uint16_t opcode);
    void after(uint16_t opcode);
    template <typename T> T* scratch(size_t n)
    {
        // Names come back the same, so the buffer only needs to exist; check_glGen* refuses
        // counts past the limit before the driver sees them.
        mScratch.assign(std::min<uint64_t>(n, mLimits.names) * sizeof(T) + sizeof(T), 0);
        return reinterpret_cast<T*>(mScratch.data());
    }
    // A recorded client-array pointer: an offset when a buffer is bound, else our shadow.
    const void* clientPointer(uint64_t value, int attribIndex);
    bool pseudo(CallReader& r, uint16_t opcode);
    // Shader and program names: the recorded program got its names from its driver, this
    // replay's come after nprgl's own programs, so a kCreated pseudo-call after each
    // glCreateShader or glCreateProgram maps the recorded name to the one made here. Names
    // a capture never announced (format version 2) are taken as they are.
    void created(GLuint made)
    {
        mMade = made;
        mMadeUnnamed = true; // until the kCreated pseudo-call after it
    }
    GLuint objectName(GLuint recorded) const
    {
        const auto it = mObjectNames.find(recorded);
        return it == mObjectNames.end() ? recorded : it->second;
    }
    const std::string& error() const { return mError; }
    // Calls the program made that the capture lacks (forwarded, not recorded), by name, with
    // the frames they were made in.
    struct Uncaptured {
        uint64_t calls = 0;
        std::vector<uint64_t> frames;
    };
    const std::map<std::string, Uncaptured>& uncaptured() const { return mUncaptured; }

    // Checks the generated decoder calls before the driver's (false: refused).
    bool checkImage(uint16_t opcode, const Image& image, GLenum format, GLenum type, GLsizei width,
                    GLsizei height, GLsizei depth);
    // Compressed texture data: imageSize bytes, or an offset into the pixel-unpack buffer.
    bool checkUnpacked(uint16_t opcode, const Image& image, size_t size);
    bool check_glDrawArrays(GLenum mode, GLint first, GLsizei count);
    bool check_glDrawElements(GLenum mode, GLsizei count, GLenum type, const void* indices,
                              const Image& image);
    bool check_glDrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count,
                                   GLenum type, const void* indices, const Image& image);
    // Issued as glDrawElements when the check found its range past the arrays.
    void issue_glDrawRangeElements(GLenum mode, GLuint start, GLuint end, GLsizei count,
                                   GLenum type, const void* indices);
    bool check_glMultiDrawArrays(GLenum mode, const GLint* first, const GLsizei* count,
                                 GLsizei drawcount);
    bool check_glArrayElement(GLint i);
    bool check_glNewList(GLuint list, GLenum mode);
    bool check_glEndList();
    bool check_glCallList(GLuint list);
    bool check_glCallLists(GLsizei n, GLenum type, const uint8_t* lists);
    bool check_glListBase(GLuint base);
    bool check_glDeleteLists(GLuint list, GLsizei range);
    bool check_glGenLists(GLsizei range);
    bool check_glEvalMesh1(GLenum mode, GLint i1, GLint i2);
    bool check_glEvalMesh2(GLenum mode, GLint i1, GLint i2, GLint j1, GLint j2);
    bool check_glBufferData(GLenum target, GLsizeiptr size, const uint8_t* data, GLenum usage);
    bool check_glCopyTexImage1D(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                                GLsizei width, GLint border);
    bool check_glCopyTexImage2D(GLenum target, GLint level, GLenum internalformat, GLint x, GLint y,
                                GLsizei width, GLsizei height, GLint border);
    // Replayed at another size than recorded: the program's viewport, scissor and the regions
    // it copies from or blits to the window scaled by (sx, sy), so that the frame is the
    // program's picture resized. Framebuffer objects keep their sizes.
    void setWindowScale(double sx, double sy)
    {
        mScaleX = sx;
        mScaleY = sy;
    }
    // The replay's window size, for what a clear covers.
    void setWindowSize(int width, int height)
    {
        mWindowWidth = width;
        mWindowHeight = height;
    }
    // The colour the frame's last clear of the whole window cleared it to, in 8 bits (to a
    // level: see issue_glClear): its background, where the program drew nothing. False when
    // no clear of the frame covered the whole window (a scissored or masked one, none at all,
    // one in a list).
    bool frameClear(uint8_t rgb[3]) const
    {
        if (!mCleared) return false;
        std::copy(mClear, mClear + 3, rgb);
        return true;
    }
    void issue_glClear(GLbitfield mask);
    void issue_glViewport(GLint x, GLint y, GLsizei width, GLsizei height);
    void issue_glScissor(GLint x, GLint y, GLsizei width, GLsizei height);
    void issue_glCopyTexImage2D(GLenum target, GLint level, GLenum internalformat, GLint x,
                                GLint y, GLsizei width, GLsizei height, GLint border);
    void issue_glCopyTexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                                   GLint x, GLint y, GLsizei width, GLsizei height);
    void issue_glBlitFramebuffer(GLint srcX0, GLint srcY0, GLint srcX1, GLint srcY1, GLint dstX0,
                                 GLint dstY0, GLint dstX1, GLint dstY1, GLbitfield mask,
                                 GLenum filter);
    bool check_glGenTextures(GLsizei n, GLuint* names) { return checkNames(n, names); }
    bool check_glGenQueries(GLsizei n, GLuint* names) { return checkNames(n, names); }
    bool check_glGenBuffers(GLsizei n, GLuint* names) { return checkNames(n, names); }
    bool check_glGenFramebuffers(GLsizei n, GLuint* names) { return checkNames(n, names); }
    bool check_glGenRenderbuffers(GLsizei n, GLuint* names) { return checkNames(n, names); }
    bool check_glGenProgramsARB(GLsizei n, GLuint* names) { return checkNames(n, names); }

private:
    // One enabled array a draw reads: bytes from `start` of a shadow slot or a buffer.
    struct ArrayUse {
        int slot = -1;        // shadow slot, or -1 for a buffer (or no data at all)
        uint64_t start = 0;   // byte offset of element 0
        uint64_t element = 0; // bytes per element
        uint64_t stride = 0;
        uint64_t bufferSize = 0; // slot -1: the buffer's size (0: no data)
    };

    bool refuse(std::string message);
    // False between glBegin and glEnd, where the driver refuses queries (and most calls).
    bool idle() const;
    GLint getInt(GLenum pname) const;
    uint64_t bufferSize(GLenum target, GLuint buffer) const;
    void addArray(GLint size, GLenum type, GLint stride, GLuint buffer, const void* pointer,
                  bool fixedSize, int count);
    // The enabled arrays, queried again when their state may have changed.
    bool queryArrays();
    // Whether the window (framebuffer 0) is bound to `binding` (GL_DRAW/READ_FRAMEBUFFER_-
    // BINDING) while the replay scales it.
    bool scalesWindow(GLenum binding) const;
    // A window rectangle scaled: its edges, so that rectangles that meet still meet.
    void scaleRect(GLint& x, GLint& y, GLsizei& width, GLsizei& height) const;
    // How many vertices from index 0 every enabled array holds (UINT64_MAX: no array);
    // `reserved`: what can be read without a fault, for the driver's range hints.
    uint64_t readableVertices(bool reserved) const;
    bool checkVertices(const char* call, uint64_t lo, uint64_t hi, bool reserved = false);
    bool checkIndices(const char* call, GLsizei count, GLenum type, const Image& image,
                      const void* indices, uint64_t& maxIndex);
    bool checkNames(GLsizei n, const void* names);
    bool chargeWork(uint64_t work);
    bool chargeBytes(uint64_t bytes);

    ShadowArrays& mArrays;
    ReplayLimits mLimits;
    std::function<bool(uint64_t)> mFrameEnd;
    uint16_t mOpcode = 0;
    int mClientActiveTexture = 0;
    std::vector<uint8_t> mScratch;
    std::vector<uint8_t> mIndices;
    int mDepth = 0;
    CallReader::Uncaptured mFrameUncaptured; // of the frame being replayed
    std::map<std::string, Uncaptured> mUncaptured;
    std::string mError;
    GLuint mMade = 0; // what the last glCreateShader or glCreateProgram made here
    bool mMadeUnnamed = false, mWarnedUnnamed = false;
    std::unordered_map<GLuint, GLuint> mObjectNames; // recorded -> made here
    std::vector<ArrayUse> mUses;
    bool mUsesValid = false;
    bool mDropRange = false;     // the next glDrawRangeElements is issued without its range
    bool mDropRangeSaid = false;
    bool mListBegun = false; // a glBegin compiled into the list being defined, not yet ended
    uint64_t mWork = 1; // of the current call, for a list being compiled
    uint64_t mTotalWork = 0;
    uint64_t mTotalBytes = 0;
    DisplayListBudget mLists;
    double mScaleX = 1.0, mScaleY = 1.0;
    GLuint mCopyFramebuffer = 0; // draws into a texture: a scaled copy stretched back
    int mWindowWidth = 0, mWindowHeight = 0;
    bool mCleared = false; // this frame (see frameClear)
    uint8_t mClear[3] = {0, 0, 0};
};

} // namespace nprgl
