#pragma once

#include "shim/Api.h"
#include "shim/ClientArrays.h"
#include "shim/ShadowArrays.h"
#include "stream/CallReader.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace nprgl {

enum class Attrib { Vertex, Normal, Color, TexCoord };

struct TrackedVertex {
    glm::vec3 position;
    glm::vec3 normal;
    glm::vec4 color;
    glm::vec2 texcoord;
};

// One polygonal draw of a frame, with the state reconstruction needs.
struct TrackedBatch {
    GLenum mode = GL_TRIANGLES;
    std::vector<TrackedVertex> vertices;
    glm::mat4 modelview{1.0f};
    glm::mat4 projection{1.0f};
    uint32_t materialId = 0;
    bool hasNormals = false;
    bool is3D = false; // perspective projection or depth test on: what nprgl stylises
};

// Follows, without a GL context, the GL state that a frame's geometry depends on — matrix
// stacks, current attributes, materials and lighting, client arrays and buffer contents,
// display lists (with glCallLists, glListBase and nesting) — by interpreting a stream's
// decoded calls, and collects the frame's polygonal batches. The first user is mesh export;
// the frame compositor will run the same tracker live.
class StateTracker {
public:
    static constexpr bool kReplays = true; // the decodeCall sink interface

    StateTracker();
    ~StateTracker();

    // Interprets one frame's encoded calls. The batches of the frame are those collected
    // since the previous FrameEnd. Returns false with a message on malformed input.
    bool runFrame(const uint8_t* data, size_t size, BlobSource* blobs, std::string& error);
    const std::vector<TrackedBatch>& frameBatches() const { return mFrameBatches; }
    uint64_t lastFrame() const { return mLastFrame; }

    // Called by the generated per-vertex attribute functions.
    void attrib(Attrib kind, float x, float y, float z, float w);

    // decodeCall sink.
    const GlDispatch& gl() const { return mSkipping ? mCompileOnly : mDispatch; }
    bool before(uint16_t opcode);
    void after(uint16_t) {}
    template <typename T>
    T* scratch(size_t n)
    {
        mScratch.assign(std::min<size_t>(n, 1 << 20) * sizeof(T) + sizeof(T), 0);
        return reinterpret_cast<T*>(mScratch.data());
    }
    const void* clientPointer(uint64_t value, int attribIndex);
    bool pseudo(CallReader& r, uint16_t opcode);

    // Handlers the tracking dispatch points at (through the current tracker).
    void begin(GLenum mode);
    void end();
    void matrixMode(GLenum mode) { mMatrixMode = mode; }
    glm::mat4& topMatrix();
    void pushMatrix();
    void popMatrix();
    void setEnabled(GLenum cap, bool on);
    void material(GLenum face, GLenum pname, const float* v);
    void newList(GLuint list, GLenum mode);
    void endList();
    void callList(GLuint list);
    void listBase(GLuint base) { mListBase = base; }
    GLuint listBaseValue() const { return mListBase; }
    void deleteLists(GLuint list, GLsizei range);
    void bindTexture(GLenum target, GLuint texture);
    void enableArray(GLenum cap, bool on);
    void clientActiveTexture(GLenum unit);
    void arrayPointer(int slot, GLint size, GLenum type, GLsizei stride, const void* pointer);
    int texCoordSlot() const { return kTexCoordArray0 + mClientActiveTexture; }
    void bindBuffer(GLenum target, GLuint buffer);
    void bufferData(GLenum target, GLsizeiptr size, const void* data);
    void bufferSubData(GLenum target, GLintptr offset, GLsizeiptr size, const void* data);
    void drawArrays(GLenum mode, GLint first, GLsizei count);
    void drawElements(GLenum mode, GLsizei count, GLenum type, const void* indices);
    void arrayElement(GLint i);
    void rect(float x1, float y1, float x2, float y2);
    bool executing() const { return !mCompiling || mCompileAndExecute; }

private:
    struct ListItem {
        std::vector<uint8_t> call; // an encoded state call, run at glCallList time
        int batch = -1;            // or a batch captured when the list was compiled
    };
    struct List {
        std::vector<ListItem> items;
        std::vector<TrackedBatch> batches;
    };
    struct ArrayBinding {
        ClientArray array;
        GLuint buffer = 0; // data in this buffer's shadow (pointer is an offset)
    };

    bool runCalls(const uint8_t* data, size_t size, bool topLevel, std::string& error);
    bool isVertexCall(uint16_t opcode) const;
    void emit(TrackedBatch batch);
    TrackedVertex arrayVertex(size_t index) const;
    bool fetch(int slot, size_t index, float out[4]) const;
    uint32_t currentMaterialId();

    GlDispatch mDispatch;
    GlDispatch mCompileOnly; // state calls of a GL_COMPILE list: kept, not followed
    bool mSkipping = false;
    ShadowArrays mArrays;
    BlobSource* mBlobs = nullptr;
    std::vector<uint8_t> mScratch;
    uint16_t mOpcode = 0;

    GLenum mMatrixMode = GL_MODELVIEW;
    std::vector<glm::mat4> mModelview{glm::mat4(1.0f)};
    std::vector<glm::mat4> mProjection{glm::mat4(1.0f)};
    std::vector<glm::mat4> mTexture{glm::mat4(1.0f)};
    TrackedVertex mCurrent{{0, 0, 0}, {0, 0, 1}, {1, 1, 1, 1}, {0, 0}};
    bool mNormalSet = false;
    bool mLighting = false, mColorMaterial = false, mDepthTest = false, mTexture2D = false;
    glm::vec4 mMaterialDiffuse{0.8f, 0.8f, 0.8f, 1.0f};
    GLuint mBoundTexture = 0;
    std::map<std::vector<float>, uint32_t> mMaterialIds;

    bool mInBegin = false;
    TrackedBatch mBatch;

    std::map<GLuint, List> mLists;
    bool mCompiling = false, mCompileAndExecute = false;
    GLuint mCompilingList = 0;
    List mCompiled;
    GLuint mListBase = 0;
    int mCallDepth = 0;

    ArrayBinding mArrayState[kArraySlotCount];
    int mClientActiveTexture = 0;
    GLuint mArrayBuffer = 0, mElementBuffer = 0;
    std::map<GLuint, std::vector<uint8_t>> mBuffers;

    std::vector<TrackedBatch> mFrameBatches;
    uint64_t mLastFrame = 0;
    bool mFrameDone = false;
};

// The tracker the generated attribute functions report to (set while one runs).
StateTracker& currentTracker();

} // namespace nprgl
