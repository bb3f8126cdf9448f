#pragma once

#include "frame/AttribStack.h"
#include "frame/ClientArrays.h"
#include "frame/LeaveRules.h"
#include "frame/MatrixStacks.h"
#include "frame/ShadowArrays.h"
#include "frame/TextureImage.h"
#include "frame/TextureTable.h"
#include "reconstruct/Batch.h"
#include "shim/Api.h"
#include "stream/CallReader.h"
#include "styles/Scene.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace nprgl {

enum class Attrib { Vertex, Normal, Color, TexCoord };

// Kept as reconstruction's own vertex, so the compositor hands the tracker's vectors to the
// Reconstructor without converting them. hasNormal always equals its batch's hasNormals.
using TrackedVertex = reconstruct::Vertex;


// One polygonal draw of a frame: its vertices and the state reconstruction needs, and its
// look (styles::Appearance), which the scene object drawn from it takes whole.
struct TrackedBatch : styles::Appearance {
    GLenum mode = GL_TRIANGLES;
    std::vector<TrackedVertex> vertices;
    glm::mat4 modelview{1.0f};
    uint32_t materialId = 0;
    bool hasNormals = false;
    bool is3D = false; // perspective projection or depth test on: what nprgl stylises
    bool held = false; // the compositor held it back (only when holding is on)
    // glMaterial colours set between glBegin and glEnd (per face or per vertex, as
    // programs set them): each from vertex `first` on; before the first, the material at
    // glBegin. Empty: the material at the draw colours every vertex.
    // GL_AMBIENT_AND_DIFFUSE sets both (skytentacles colours its tentacles so, vertex by
    // vertex); GL_AMBIENT the ambient alone (what GL's lighting, the replica's, reflects).
    struct MaterialChange {
        uint32_t first = 0;
        glm::vec4 diffuse{0.8f, 0.8f, 0.8f, 1.0f};
        glm::vec3 ambient{0.2f};
        bool setsDiffuse = true, setsAmbient = false;
    };
    std::vector<MaterialChange> materials;
    glm::vec4 beginMaterial{0.8f, 0.8f, 0.8f, 1.0f}; // the diffuse at glBegin
    glm::vec3 beginAmbient{0.2f};                     // and the ambient
    glm::ivec4 viewport{0, 0, 0, 0};
    uint64_t contentHash = 0; // reconstruct::hashVertices of the kept batch (0: not computed)
    // Drawn under glFrontFace(GL_CW): reconstruction assembles it the other way round, so
    // that the program's front faces are counter-clockwise in every batch of an object
    // (xscreensaver's involute gears turn the front face between the rings of one gear).
    bool clockwise = false;
    reconstruct::QuadCut quadCut = reconstruct::QuadCut::V0V2; // as the driver cuts its quads
};

// What reconstruction takes of a tracked batch besides its vertices (which the caller lends
// or copies): the fields its triangles and its object depend on.
inline void assignAssembly(reconstruct::Batch& b, const TrackedBatch& t)
{
    b.mode = t.mode;
    b.modelview = t.modelview;
    b.materialId = t.materialId;
    b.clockwise = t.clockwise;
    b.quadCut = t.quadCut;
}

// Follows, without a GL context, the GL state that a frame's geometry depends on — matrix
// stacks, current attributes, materials and lighting, client arrays and buffer contents,
// display lists (with glCallLists, glListBase and nesting) — by interpreting a stream's
// decoded calls, and collects the frame's polygonal batches, for the compositor (live) and
// for replay and mesh export. Defined by state group: StateTracker.cpp (frames, immediate
// mode, enables, the batch finisher), TrackerArrays.cpp, TrackerLists.cpp,
// TrackerTextures.cpp, TrackerLighting.cpp and TrackerHold.cpp (what is held and why).
class StateTracker {
public:
    static constexpr bool kReplays = true; // the decodeCall sink interface

    StateTracker();
    ~StateTracker();

    // Interprets one frame's encoded calls. The batches of the frame are those collected
    // since the previous FrameEnd. Returns false with a message on malformed input. opcodes:
    // the capture's numbering (null: this build's).
    bool runFrame(const uint8_t* data, size_t size, BlobSource* blobs, std::string& error,
                  const OpcodeMap* opcodes = nullptr);
    const std::vector<TrackedBatch>& frameBatches() const { return mFrameBatches; }

    // Live use by the compositor: interprets calls as they are recorded, frames and all.
    bool feed(const uint8_t* data, size_t size, BlobSource* blobs, std::string& error);
    // Holding: batches the compositor holds back are marked `held`, and only those are kept.
    void setHolding(bool on) { mHolding = on; }
    // Lit batches take the colours GL's lighting gives each vertex (FixedLighting), and flat
    // shading its provoking colours, instead of the material's colour the shading styles
    // shade from: for the `replica` style.
    void setProgramLighting(bool on) { mProgramLighting = on; }
    // The program draws into a framebuffer it reads back (colour-coded picking, results
    // computed by drawing): its pixels are data, so nothing is held (the reason below).
    void setDrawingData(bool on) { mDrawingData = on; }
    static constexpr const char* kDrawingDataWhy =
        "a framebuffer the program reads back (picking, results computed by drawing)";
    // Would a draw of `mode` issued now be held back? Polygonal, executed now (not only
    // compiled into a list), 3D, and drawn in plain state (GL_RENDER, filled, no blending,
    // alpha or stencil test, all colour channels written): what the styles can re-draw.
    bool wouldHold(GLenum mode) const;
    // Would glCallList(list) issued now be held back as a whole? Its draws are all polygonal
    // (no bitmaps, pixels, lines or points, also in the lists it calls).
    // Why a list's polygons would be left as the program draws them (nullptr: they would
    // not, or it draws none).
    const char* listUnstylable(GLuint list) const;
    // The same for the lists of a glCallLists: null when they draw no polygons.
    const char* listsUnstylable(GLsizei n, GLenum type, const void* lists) const;
    bool wouldHoldList(GLuint list) const;
    // glCallLists is held as a whole when every list it calls would be (text drawn from
    // bitmap-font lists never is).
    bool wouldHoldLists(GLsizei n, GLenum type, const void* lists) const;
    // No list it calls (at any depth) draws what is never held; anyBatch: one holds a batch.
    bool listHoldable(GLuint list, bool& anyBatch) const;
    // A 3D polygon draw issued now would not be held because of this state (for the log), or
    // null. 2D drawing (no depth test, no perspective) is not held and needs no reason.
    const char* unstylableState() const;
    // Could a draw of `mode` issued now, left only for its blending, be a further pass over
    // geometry held for the scene (a detail, light, shine or fog layer of a multi-pass
    // surface)? watchRepeats(), feed it, then ask repeatedAll().
    bool mayLayer(GLenum mode) const;
    // The same for a display list called now (one that draws only what could be held).
    bool mayLayerList(GLuint list) const;
    // Whether every polygon batch fed since watchRepeats() repeated held geometry (same
    // mode, positions, matrices and culling as one of the last held batches): a pass over
    // that object, not kept; the caller merges it (or draws all of it when not every batch
    // repeats). Ends the watch.
    void watchRepeats() { mWatch = {true, 0, 0}; }
    bool repeatedAll();
    // Held blended batches that repeated held geometry, merged without asking (translucent
    // passes), over the run.
    uint64_t mergedPasses() const { return mMergedPasses; }
    // Texture units (bits) a draw issued now layers over its surface's texture, which the
    // styles do not draw (see surfaceUnit).
    uint32_t droppedLayers() const;
    // The program's shaders (GLSL or ARB programs) draw what is issued now.
    bool ownShaders() const;
    // The unit whose lightmap gives a draw issued now its light (no GL lighting), or -1.
    int lightmapUnit() const { return mAttrib.lighting ? -1 : lightUnit(); }
    // A draw issued now adds light (GL_ONE or GL_SRC_ALPHA onto GL_ONE) through the
    // fixed-function pipeline: a glow, a flare, a particle. With what it is drawn from.
    bool additiveGlow(bool& textured, bool& sourceAlpha) const;
    // What a display list called now draws, by its own state calls (glEnable/glDisable of
    // GL_TEXTURE_2D and GL_BLEND, glBindTexture, glBlendFunc, and those of the lists it
    // calls) from the state at the call: for what takes one setting for the whole call (the
    // glow ink's texturing, whether the styles may hold it).
    struct ListDraws {
        size_t textured = 0, untextured = 0; // vertices with unit 0's texture on and off
        bool blendsLeft = false; // a draw blended in a way the styles leave (additive...)
    };
    ListDraws listDraws(GLuint list) const;
    bool is3D() const;
    void setRenderMode(GLenum mode) { mRenderMode = mode; }
    GLenum renderMode() const { return mRenderMode; }
    // The driver's attribute stack depths (GL_MAX_ATTRIB_STACK_DEPTH, ..._CLIENT_...).
    void setStackLimits(int attrib, int client)
    {
        mMaxAttribDepth = attrib;
        mMaxClientDepth = client;
    }
    void setViewport(const glm::ivec4& v) { mAttrib.viewport = v; }
    void setScissor(const glm::ivec4& box) { mAttrib.scissor = box; }
    void setScissorTest(bool on) { mAttrib.scissorTest = on; }
    // GL clamps both to [0, 1].
    void setDepthRange(float n, float f)
    {
        mAttrib.depthRange = {std::clamp(n, 0.0f, 1.0f), std::clamp(f, 0.0f, 1.0f)};
    }
    const glm::vec2& depthRange() const { return mAttrib.depthRange; }
    // The scissor test's state now: on, and its box.
    bool scissorTest() const { return mAttrib.scissorTest; }
    // glColorMask's (AttribState::colorMaskRgb and its kin).
    bool colourMaskRgb() const { return mAttrib.colorMaskRgb(); }
    bool colourMaskAlpha() const { return mAttrib.colorMaskAlpha(); }
    bool colourMaskNone() const { return mAttrib.colorMaskNone(); }
    const glm::ivec4& scissor() const { return mAttrib.scissor; }
    const glm::ivec4& viewport() const { return mAttrib.viewport; }
    // Moves the held batches out (the frame's batch list starts empty again). The batches
    // `out` held before give their vertex vectors back to the pool first.
    void takeBatches(std::vector<TrackedBatch>& out);
    // Takes the batches' vertex vectors (emptied, capacity kept) for the next frames' batches:
    // no allocation and no page faults per frame once the sizes repeat.
    void recycle(std::vector<TrackedBatch>& batches);
    uint64_t lastFrame() const { return mLastFrame; }

    // Called by the generated per-vertex attribute functions.
    void attrib(Attrib kind, float x, float y, float z, float w);
    // glMultiTexCoord: unit 0's is glTexCoord's; the others' are kept for the draws that
    // texture from that unit alone.
    void unitTexCoord(GLenum target, float x, float y, float z, float w);

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
    void matrixMode(GLenum mode) { mMatrices.setMode(mode); }
    glm::mat4& topMatrix() { return mMatrices.top(); }
    void pushMatrix() { mMatrices.push(); }
    void popMatrix() { mMatrices.pop(); }
    void setEnabled(GLenum cap, bool on);
    void useProgram(GLuint program) { mProgram = program; }
    void material(GLenum face, GLenum pname, const float* v);
    // glTexGen: the mode, or the object or eye plane (four values; the eye plane is taken
    // into eye space by the current modelview, as GL does).
    void texGen(GLenum coord, GLenum pname, const double* values, size_t count);
    // A glMaterial between glBegin and glEnd: its diffuse colour from the batch's next vertex.
    void batchMaterial(GLenum face, GLenum pname, const float* v);
    void newList(GLuint list, GLenum mode);
    void endList();
    void callList(GLuint list);
    // glCallLists: held as a whole (wouldHoldLists), or let through, and then none of the
    // batches of the lists it calls is held (the driver draws them).
    void callLists(GLsizei n, GLenum type, const void* lists);
    void noteCompiledCall(GLuint list) { mCompiled.calls.push_back(list); }
    void listBase(GLuint base) { mListBase = base; }
    GLuint listBaseValue() const { return mListBase; }
    void deleteLists(GLuint list, GLsizei range);
    void bindTexture(GLenum target, GLuint texture);
    // glTexEnv: the active unit's GL_TEXTURE_ENV_MODE.
    void texEnv(GLenum target, GLenum pname, GLenum mode);
    // glTexImage2D: level 0 of a 2D texture names the bound texture's content (hashed); its
    // alpha is its internal format's (TextureAlpha).
    void texImage2D(GLenum target, GLint level, GLint internalFormat, GLsizei width,
                    GLsizei height, GLenum format, GLenum type, const void* pixels);
    // glCopyTexImage2D and glTexStorage2D: level 0 of the bound 2D texture is made in
    // `internalFormat` with content not known here: a copy of the framebuffer, or none yet
    // (`empty`: glTexSubImage2D fills it, as after glTexImage2D without pixels).
    void texStorage2D(GLenum target, GLint level, GLenum internalFormat, bool empty);
    // glTexSubImage2D: what it does to level 0's opacity.
    void texSubImage2D(GLenum target, GLint level, GLint x, GLint y, GLsizei width,
                       GLsizei height, GLenum format, GLenum type, const void* pixels);
    // GL wrote level 0 of a texture itself: the bound one's (glCopyTexSubImage2D), or one
    // attached to a framebuffer (rendered into).
    void texCopiedInto(GLenum target, GLint level);
    void textureAttached(GLuint texture) { mTextures.overwritten(texture); }
    // The decoder's check of an image argument (format, type, sizes follow): how many bytes
    // the call carries.
    template <typename... Shape>
    bool checkImage(uint16_t, const CallReader::Image& image, Shape...)
    {
        mImageBytes = image.mode == CallReader::Image::kBytes ? image.size : 0;
        return true;
    }
    // XXH3 of a texture's level-0 image with its size and format (0: never uploaded here):
    // what names a texture across runs, where its GL name may differ.
    uint64_t textureHash(GLuint texture) const;
    // Rules: draws on unit 0 with a texture of these contents, and draws in these states, are
    // left as the program draws them (counted with their reason).
    void setRules(LeaveRules rules)
    {
        rules.normalise();
        mRules = std::move(rules);
    }
    const LeaveRules& rules() const { return mRules; }
    void activeTexture(GLenum unit);
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
    bool compiling() const { return mCompiling; }
    void light(GLenum light, GLenum pname, const float* v);
    void lightModel(GLenum pname, const float* v);
    void shadeModel(GLenum mode) { mAttrib.flatShade = mode == GL_FLAT; }
    void blendFunc(GLenum src, GLenum dst);
    void depthMask(bool on);
    void depthFunc(GLenum func);
    void alphaFunc(GLenum func, float ref);
    void polygonOffset(float factor, float units)
    {
        mAttrib.offsetFactor = factor;
        mAttrib.offsetUnits = units;
    }
    void cullMode(GLenum mode) { mAttrib.cullMode = mode; }
    void frontFace(GLenum mode) { mAttrib.frontFace = mode; }
    void fog(GLenum pname, const float* v, size_t count);
    // GL_FOG_MODE while GL_FOG is on, else 0.
    GLenum fogMode() const { return mAttrib.fog ? mAttrib.fogMode : 0; }
    // Blending that changes a pixel (GL_BLEND on, functions other than GL_ONE, GL_ZERO).
    bool blending() const;
    // Blending on with GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA.
    bool translucent() const;
    // The enabled light with the brightest diffuse colour (0 when none is on).
    size_t keyLight() const;
    // The enabled lights as the styles take them (SceneLights).
    void litBy(styles::SceneLights& out) const;
    void polygonMode(GLenum face, GLenum mode);
    void colorMaterial(GLenum face, GLenum mode)
    {
        // Another value is refused by the driver.
        if (face != GL_FRONT && face != GL_BACK && face != GL_FRONT_AND_BACK) return;
        if (mode == GL_EMISSION || mode == GL_AMBIENT || mode == GL_DIFFUSE ||
            mode == GL_SPECULAR || mode == GL_AMBIENT_AND_DIFFUSE) {
            mAttrib.colorMaterialMode = mode;
            mAttrib.colorMaterialFace = face;
        }
    }
    void colorMask(bool r, bool g, bool b, bool a)
    {
        mAttrib.colorMask = uint8_t((r ? 1u : 0u) | (g ? 2u : 0u) | (b ? 4u : 0u) | (a ? 8u : 0u));
    }
    void pushAttrib(GLbitfield mask);
    void popAttrib();
    void pushClientAttrib();
    void popClientAttrib();
    void otherDraw(); // a bitmap, pixel rectangle, line or point: never held

private:
    struct ListItem {
        std::vector<uint8_t> call; // an encoded state call, run at glCallList time
        int batch = -1;            // or a batch captured when the list was compiled
    };
    struct List {
        std::vector<ListItem> items;
        std::vector<TrackedBatch> batches;
        bool otherDraws = false; // bitmaps, pixels, lines, points, glCallLists
        std::vector<GLuint> calls; // lists it calls with glCallList
        struct Inherits {
            bool color = false, normal = false, texcoord = false;
        };
        std::vector<Inherits> inherits; // per batch: attributes taken at glCallList time
    };
    struct ArrayBinding {
        ClientArray array;
        GLuint buffer = 0; // data in this buffer's shadow (pointer is an offset)
    };
    // An enabled array's bytes as one draw reads them: looked up once per draw, not per
    // vertex. Element i is at base + i * stride when i * stride + elem <= limit.
    struct ArraySource {
        const uint8_t* base = nullptr; // null: the array gives nothing
        size_t limit = 0, stride = 0, elem = 0;
        GLenum type = GL_FLOAT;
        int count = 0; // components read (at most 4)
        bool normalize = false, bgra = false;
    };
    struct DrawSources {
        ArraySource vertex, normal, color, texcoord, lightcoord;
    };

    void callListBody(GLuint list);
    // The texture unit a draw issued now takes the surface's texture from: the lowest
    // textured unit with coordinates of its own (0 also when nothing is textured), or -1 when
    // its texture is not a 2D one. Units above it layer light or effects over it
    // (lightmaps, shadows, environment maps): droppedLayers(), not drawn by the styles.
    int surfaceUnit() const;
    // The unit of a lightmap over the surface's texture: the first layer that modulates it
    // (GL_MODULATE) with a 2D texture on coordinates of its own; -1 when there is none.
    int lightUnit() const;
    // A batch blended by alpha whose alpha is 1 everywhere (its colours', its texture's).
    bool opaqueAlpha(const TrackedBatch& batch) const;
    // The specular light a lit batch shows evenly (the least over its vertices) added to
    // its colours.
    void addEvenSpecular(TrackedBatch& batch) const;
    // Under GL_REPLACE (or GL_DECAL with an opaque texture) the picture shows the texture's
    // colour, not the lit or current one: the batch's colours become white.
    void replacedByTexture(TrackedBatch& batch) const;
    // A rule (leave_texture or leave_state) leaves a draw issued now.
    bool leftByRule() const;
    // The winding the current culling removes, in the winding batches are assembled in
    // (TrackedBatch::culled).
    GLenum culledWinding() const;
    // Does a batch draw the same triangles as one held this frame (a pass over it)? An
    // alpha-blended layer over a translucent batch is not a pass over a surface but the next
    // layer of a layered decal, whose picture is its own: `layer` says the batch is
    // alpha-blended, and then translucent batches are no base.
    bool repeatsHeld(const TrackedBatch& batch, bool layer) const;
    static uint64_t passKey(const TrackedBatch& batch);
    void indexBatch(const TrackedBatch& batch);
    // Why surfaceUnit() is -1.
    const char* multitexturing() const;
    // What of the fixed pipeline's state the styles cannot follow (stencil, lines or points,
    // a partial colour mask, a full attribute stack), or null.
    const char* pipelineLimit() const;
    // The surface's unit (a bit) and the layers above it (bits).
    uint32_t texturedUnits(uint32_t& layers) const;
    // The enabled units whose texture is a depth texture (bits): a shadow map compared by
    // the fixed pipeline, never a surface's texture or a lightmap, only a layer not drawn.
    uint32_t depthUnits() const;
    // Makes mCurrent's texture coordinates the surface unit's (at each draw).
    void followSurfaceUnit();
    // The surface unit's 2D texture as the styles use it: 0 when off or on generated
    // coordinates.
    GLuint detailTexture() const;
    void applyTextureMatrices(TrackedBatch& batch) const;
    // A bound name as the scene takes it: the default texture as styles::kDefaultTexture.
    GLuint sceneTexture(GLuint name) const;
    // The 2D texture a unit applies, as the scene takes it (unit 0's only while enabled).
    GLuint unitTexture(int unit) const;
    styles::GeneratedTexture generatedTexture() const;
    void noteListArrays();
    bool runCalls(const uint8_t* data, size_t size, bool topLevel, std::string& error);
    bool isVertexCall(uint16_t opcode) const;
    static bool runsWhileCompiling(uint16_t opcode);
    void emit(TrackedBatch&& batch);
    // Whether a draw issued now takes the current normal as its own (see mNormalFresh).
    bool currentNormalCounts() const;
    // A dropped layer's texture env on unit as c scale + offset; false when not followed.
    bool layerEffect(int unit, glm::vec3& scale, glm::vec3& offset) const;
    void layerEffects(TrackedBatch& batch) const;
    // A generated texture on GL_OBJECT_LINEAR planes becomes the batch's texture on
    // coordinates made from its vertices.
    void bakeObjectLinear(TrackedBatch& batch) const;
    bool keep(TrackedBatch& batch);
    std::vector<TrackedVertex> takeVertices();
    void recycle(std::vector<TrackedVertex>&& vertices);
    DrawSources drawSources();
    ArraySource source(int slot) const;
    TrackedVertex arrayVertex(const DrawSources& from, size_t index, bool hasNormal) const;
    static bool fetch(const ArraySource& from, size_t index, float out[4]);
    uint32_t currentMaterialId();

    GlDispatch mDispatch{}; // slots of calls never recorded stay null: nothing decodes them
    GLuint mProgram = 0;    // glUseProgram's (GLSL), not part of the attribute stacks
    GlDispatch mCompileOnly{}; // state calls of a GL_COMPILE list: kept, not followed
    bool mSkipping = false;
    ShadowArrays mArrays;
    BlobSource* mBlobs = nullptr;
    const OpcodeMap* mOpcodes = nullptr; // of the capture fed to runFrame
    std::vector<uint8_t> mScratch;
    uint16_t mOpcode = 0;

    MatrixStacks mMatrices;
    TrackedVertex mCurrent{{0, 0, 0}, {0, 0, 1}, {1, 1, 1, 1}, {0, 0}, {0, 0}};
    bool mNormalSet = false;
    // glNormal was called since the last draw (or inside the open glBegin): the current
    // normal was set for the next draw, not left over from another object's.
    bool mNormalFresh = false;
    AttribStack mAttribs;
    AttribState& mAttrib = mAttribs.current(); // the state the calls change
    GLuint mBoundTexture = 0; // unit 0's GL_TEXTURE_2D
    std::array<GLuint, 8> mUnitTextures{}; // every unit's GL_TEXTURE_2D, for uploads
    std::array<glm::vec2, 8> mUnitTexcoords{}; // every unit's current coordinates
    int mSurfaceUnit = 0; // mCurrent.texcoord is this unit's
    int mLightUnit = -1;  // mCurrent.lightcoord is this unit's (-1: no lightmap)
    std::array<GLuint, 8> mUnitCubeTextures{}; // every unit's GL_TEXTURE_CUBE_MAP
    TextureTable mTextures; // what each texture's uploads made of it
    LeaveRules mRules;
    size_t mImageBytes = 0; // of the call being decoded
    int mActiveUnit = 0;
    // What glPushAttrib saves beside AttribState: GL_TEXTURE_BIT's bindings and active unit,
    // GL_CURRENT_BIT's colour, normal and every unit's coordinates (a program that binds or
    // sets them inside a push finds the old ones after the pop, and so does the tracker).
    struct SavedCurrent {
        GLbitfield mask = 0;
        GLuint boundTexture = 0;
        std::array<GLuint, 8> unitTextures{}, unitCubeTextures{};
        int activeUnit = 0;
        glm::vec4 color{1.0f};
        glm::vec3 normal{0.0f, 0.0f, 1.0f};
        bool hasNormal = false;
        std::array<glm::vec2, 8> texcoords{};
    };
    std::vector<SavedCurrent> mSavedCurrent;
    // While a list compiles: which current attributes the list sets itself (the others come
    // from the state when the list is called).
    bool mListSetsColor = false, mListSetsNormal = false, mListSetsTexCoord = false;
    bool mHolding = false;
    bool mProgramLighting = false;
    bool mDrawingData = false; // setDrawingData
    int mHoldingList = 0; // > 0 while a held glCallList expands
    int mPassingList = 0; // > 0 while a list the driver draws itself expands
    GLenum mRenderMode = GL_RENDER;
    int mClientDepth = 0;
    int mMaxAttribDepth = 16, mMaxClientDepth = 16; // GL's minimum until told
    std::map<std::array<float, 7>, uint32_t> mMaterialIds;

    bool mInBegin = false;
    TrackedBatch mBatch;

    std::map<GLuint, List> mLists;
    bool mCompiling = false, mCompileAndExecute = false;
    GLuint mCompilingList = 0;
    List mCompiled;
    GLuint mListBase = 0;
    int mCallDepth = 0;
    int mListDepth = 0; // of display lists being run (mCallDepth counts batch blobs too)
    // List items run by the current top-level glCallList(s): lists calling themselves more
    // than once would otherwise run 2^64 of them within the nesting limit (a hostile capture).
    static constexpr uint64_t kListWorkLimit = uint64_t(1) << 20;
    uint64_t mListWork = 0;
    bool mListWorkSaid = false;

    ArrayBinding mArrayState[kArraySlotCount];
    int mClientActiveTexture = 0;
    GLuint mArrayBuffer = 0, mElementBuffer = 0;
    // What glPopClientAttrib restores, as the recorder does: the stream's buffer offsets are
    // offsets exactly when the recorder's bindings say so, which must be the tracker's too.
    struct ClientState {
        std::array<ArrayBinding, kArraySlotCount> arrays;
        int clientActiveTexture = 0;
        GLuint arrayBuffer = 0, elementBuffer = 0;
    };
    std::vector<ClientState> mClientStack;
    std::map<GLuint, std::vector<uint8_t>> mBuffers;

    std::vector<TrackedBatch> mFrameBatches;
    // mFrameBatches (but depth-only passes) by passKey: where a pass finds its surface.
    std::unordered_multimap<uint64_t, uint32_t> mPassIndex;
    struct RepeatWatch {
        bool on = false;
        uint32_t repeated = 0; // polygon batches that repeated held geometry
        uint32_t others = 0;   // polygon batches that did not
    } mWatch;
    uint64_t mMergedPasses = 0;
    // Vertex vectors of earlier batches, last frame's first batch at the back.
    std::vector<std::vector<TrackedVertex>> mVertexPool;
    size_t mPoolBytes = 0;
    uint64_t mLastFrame = 0;
    bool mFrameDone = false;
};

} // namespace nprgl
