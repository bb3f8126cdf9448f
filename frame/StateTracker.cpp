#include "frame/StateTracker.h"

#include "frame/TrackerDispatch.h"
#include "frame/TrackerGl.h"
#include "frame/FixedLighting.h"

#include "common/Log.h"

#include "stream/CallDecoder.h"
#include "stream/Opcodes.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <xxhash.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

namespace nprgl {

using namespace tracker;

namespace {

// Whether the alpha test passes a fragment of alpha 1.
bool passesAlphaOne(GLenum func, float ref)
{
    switch (func) {
    case GL_ALWAYS: return true;
    case GL_GREATER: return ref < 1.0f;
    case GL_GEQUAL: return ref <= 1.0f;
    case GL_NOTEQUAL: return ref != 1.0f;
    case GL_EQUAL: return ref == 1.0f;
    case GL_LEQUAL: return ref >= 1.0f;
    case GL_LESS: return ref > 1.0f;
    default: return false;
    }
}

// Capacity the vertex pool keeps at most (a frame's worth for large scenes).
constexpr size_t kPoolBytes = size_t(256) << 20;

} // namespace

StateTracker::StateTracker()
{
    fillTrackerDispatch(mDispatch, mCompileOnly);
}

StateTracker::~StateTracker() = default;

bool StateTracker::runFrame(const uint8_t* data, size_t size, BlobSource* blobs,
                            std::string& error, const OpcodeMap* opcodes)
{
    mOpcodes = opcodes;
    if (mFrameDone) {
        recycle(mFrameBatches);
        mFrameBatches.clear();
        mPassIndex.clear();
        mFrameDone = false;
    }
    return feed(data, size, blobs, error);
}

bool StateTracker::feed(const uint8_t* data, size_t size, BlobSource* blobs, std::string& error)
{
    const TrackerScope scope(*this);
    mBlobs = blobs;
    return runCalls(data, size, true, error);
}

void StateTracker::takeBatches(std::vector<TrackedBatch>& out)
{
    recycle(out);
    out.swap(mFrameBatches);
    mFrameBatches.clear();
    mPassIndex.clear();
}

void StateTracker::recycle(std::vector<TrackedBatch>& batches)
{
    // Last first, so that the next frame's first batch gets this frame's first vector back.
    for (auto it = batches.rbegin(); it != batches.rend(); ++it) recycle(std::move(it->vertices));
}

void StateTracker::recycle(std::vector<TrackedVertex>&& vertices)
{
    const size_t bytes = vertices.capacity() * sizeof(TrackedVertex);
    if (bytes == 0 || mPoolBytes + bytes > kPoolBytes) {
        std::vector<TrackedVertex>().swap(vertices);
        return;
    }
    vertices.clear();
    mVertexPool.push_back(std::move(vertices));
    mPoolBytes += bytes;
}

std::vector<TrackedVertex> StateTracker::takeVertices()
{
    if (mVertexPool.empty()) return {};
    std::vector<TrackedVertex> v = std::move(mVertexPool.back());
    mVertexPool.pop_back();
    mPoolBytes -= v.capacity() * sizeof(TrackedVertex);
    return v;
}

bool StateTracker::repeatedAll()
{
    const bool all = mWatch.repeated > 0 && mWatch.others == 0;
    mWatch = {};
    return all;
}

void StateTracker::pushAttrib(GLbitfield mask)
{
    const size_t depth = mAttribs.depth();
    mAttribs.push(mask);
    if (mAttribs.depth() == depth) return; // the driver's overflow: nothing saved
    SavedCurrent s;
    s.mask = mask;
    s.boundTexture = mBoundTexture;
    s.unitTextures = mUnitTextures;
    s.unitCubeTextures = mUnitCubeTextures;
    s.activeUnit = mActiveUnit;
    s.color = mCurrent.color;
    s.normal = mCurrent.normal;
    s.hasNormal = mCurrent.hasNormal;
    s.texcoords = mUnitTexcoords;
    s.texcoords[size_t(mSurfaceUnit)] = mCurrent.texcoord;
    mSavedCurrent.push_back(s);
}

void StateTracker::popAttrib()
{
    const size_t depth = mAttribs.depth();
    mAttribs.pop();
    if (mAttribs.depth() == depth || mSavedCurrent.empty()) return;
    const SavedCurrent s = mSavedCurrent.back();
    mSavedCurrent.pop_back();
    if (s.mask & GL_TEXTURE_BIT) {
        mBoundTexture = s.boundTexture;
        mUnitTextures = s.unitTextures;
        mUnitCubeTextures = s.unitCubeTextures;
        mActiveUnit = s.activeUnit;
    }
    if (s.mask & GL_CURRENT_BIT) {
        mCurrent.color = s.color;
        mCurrent.normal = s.normal;
        mCurrent.hasNormal = s.hasNormal;
        mUnitTexcoords = s.texcoords;
        mCurrent.texcoord = mUnitTexcoords[size_t(mSurfaceUnit)];
        if (mLightUnit >= 0) mCurrent.lightcoord = mUnitTexcoords[size_t(mLightUnit)];
    }
}

void StateTracker::blendFunc(GLenum src, GLenum dst)
{
    mAttrib.blendSrc = src;
    mAttrib.blendDst = dst;
}

void StateTracker::depthMask(bool on) { mAttrib.depthMask = on; }

void StateTracker::depthFunc(GLenum func) { mAttrib.depthFunc = func; }

void StateTracker::fog(GLenum pname, const float* v, size_t count)
{
    AttribState& a = mAttrib;
    switch (pname) {
    case GL_FOG_MODE: {
        const GLenum mode = enumOf(v[0]);
        if (mode == GL_LINEAR || mode == GL_EXP || mode == GL_EXP2) a.fogMode = mode;
        break;
    }
    case GL_FOG_START: a.fogStart = v[0]; break;
    case GL_FOG_END: a.fogEnd = v[0]; break;
    case GL_FOG_DENSITY:
        if (v[0] >= 0.0f) a.fogDensity = v[0]; // a negative one is GL_INVALID_VALUE
        break;
    case GL_FOG_COLOR:
        if (count >= 3) a.fogColour = glm::clamp(glm::vec3(v[0], v[1], v[2]), 0.0f, 1.0f);
        break;
    default: break;
    }
}

void StateTracker::alphaFunc(GLenum func, float ref)
{
    if (func < GL_NEVER || func > GL_ALWAYS) return; // GL_INVALID_ENUM: nothing changes
    mAttrib.alphaFunc = func;
    mAttrib.alphaRef = std::clamp(ref, 0.0f, 1.0f);
}

void StateTracker::polygonMode(GLenum face, GLenum mode)
{
    const bool fill = mode == GL_FILL;
    if (face == GL_FRONT || face == GL_FRONT_AND_BACK) mAttrib.fillFront = fill;
    if (face == GL_BACK || face == GL_FRONT_AND_BACK) mAttrib.fillBack = fill;
}

void StateTracker::otherDraw()
{
    if (mCompiling) mCompiled.otherDraws = true;
}

bool StateTracker::isVertexCall(uint16_t opcode) const
{
    // The recorder's client-array data and batch references are geometry too.
    if (opcode == op::kArrayData || opcode == op::kBatchRef) return true;
    return opcode < op::kCount && (mInBegin || (kOpcodeFacts[opcode] & fact::kVertex));
}

bool StateTracker::runsWhileCompiling(uint16_t opcode)
{
    return opcode < op::kCount && (kOpcodeFacts[opcode] & fact::kRunsWhileCompiling);
}

bool StateTracker::runCalls(const uint8_t* data, size_t size, bool topLevel, std::string& error)
{
    CallReader r(data, size, mBlobs, mOpcodes);
    while (!r.atEnd()) {
        const size_t start = r.offset();
        const uint16_t opcode = r.opcode();
        if (!r.ok()) break;
        // While a list compiles (GL_COMPILE), state calls are kept for glCallList and not
        // run; geometry is run so that its batches are captured into the list.
        // A list that a list being compiled calls (GL_COMPILE_AND_EXECUTE runs it) is in the
        // new list as its glCallList: its own calls are not compiled into it a second time.
        const bool listControl = opcode == op::glNewList || opcode == op::glEndList;
        const bool keep = mCompiling && mListDepth == 0 && !listControl &&
                          !isVertexCall(opcode) && !runsWhileCompiling(opcode);
        const bool skip = keep && !mCompileAndExecute;
        mSkipping = skip; // decoded (for its bytes and checks) but not followed
        const bool ok = decodeCall(r, opcode, *this);
        mSkipping = false;
        if (!ok) break;
        if (keep) {
            ListItem item;
            item.call.assign(data + start, data + r.offset());
            mCompiled.items.push_back(std::move(item));
        }
        if (opcode == op::kFrameEnd && !topLevel) {
            r.fail("frame end inside a display list");
        }
    }
    if (!r.ok()) {
        error = r.error();
        return false;
    }
    return true;
}

bool StateTracker::before(uint16_t opcode)
{
    mOpcode = opcode;
    return true;
}

bool StateTracker::pseudo(CallReader& r, uint16_t opcode)
{
    if (opcode == op::kFrameEnd) {
        mLastFrame = r.get<uint64_t>();
        mFrameDone = true;
        return r.ok();
    }
    if (opcode == op::kArrayData) return mArrays.apply(r);
    if (opcode == op::kUncaptured) {
        CallReader::Uncaptured ignored; // what the recorder could not follow either
        return r.getUncaptured(ignored);
    }
    if (opcode == op::kCreated) { // the replay's names are the replaying sink's concern
        r.get<uint32_t>();
        return r.ok();
    }
    if (opcode == op::kBatchRef) {
        const std::vector<uint8_t>* blob = r.getBlobRef();
        if (!blob) return false;
        if (mCallDepth >= 64) {
            r.fail("batch references nested too deep");
            return false;
        }
        ++mCallDepth;
        std::string error;
        const bool ok = runCalls(blob->data(), blob->size(), false, error);
        --mCallDepth;
        if (!ok) r.fail("in a referenced batch: " + error);
        return ok;
    }
    r.fail("unknown opcode " + std::to_string(opcode));
    return false;
}

void StateTracker::attrib(Attrib kind, float x, float y, float z, float w)
{
    switch (kind) {
    case Attrib::Normal:
        mCurrent.normal = {x, y, z};
        mCurrent.hasNormal = mNormalSet = mNormalFresh = true;
        mListSetsNormal = mListSetsNormal || mCompiling;
        break;
    case Attrib::Color:
        mCurrent.color = {x, y, z, w};
        mListSetsColor = mListSetsColor || mCompiling;
        break;
    case Attrib::TexCoord:
        // glTexCoord is unit 0's: mCurrent holds the surface unit's.
        if (mSurfaceUnit == 0) mCurrent.texcoord = {x, y};
        else mUnitTexcoords[0] = {x, y};
        if (mLightUnit == 0) mCurrent.lightcoord = {x, y};
        mListSetsTexCoord = mListSetsTexCoord || mCompiling;
        break;
    case Attrib::Vertex: {
        if (!mInBegin) return;
        TrackedVertex& v = mBatch.vertices.emplace_back(mCurrent);
        if (w != 0.0f && w != 1.0f) v.position = glm::vec3(x, y, z) / w;
        else v.position = glm::vec3(x, y, z);
        break;
    }
    }
}

void StateTracker::unitTexCoord(GLenum target, float x, float y, float z, float w)
{
    if (target < GL_TEXTURE0 || target >= GL_TEXTURE0 + mUnitTexcoords.size()) return;
    const int u = int(target - GL_TEXTURE0);
    if (u == 0) return attrib(Attrib::TexCoord, x, y, z, w);
    if (u == mSurfaceUnit) mCurrent.texcoord = {x, y};
    else mUnitTexcoords[size_t(u)] = {x, y};
    if (u == mLightUnit) mCurrent.lightcoord = {x, y};
    mListSetsTexCoord = mListSetsTexCoord || mCompiling;
}

void StateTracker::begin(GLenum mode)
{
    followSurfaceUnit();
    recycle(std::move(mBatch.vertices)); // a glBegin without glEnd before it
    mInBegin = true;
    mBatch = TrackedBatch();
    mBatch.vertices = takeVertices();
    mBatch.mode = mode;
    mBatch.hasNormals = currentNormalCounts();
    mBatch.beginMaterial = mAttrib.material.diffuse;
    mBatch.beginAmbient = mAttrib.material.ambient;
    mNormalFresh = false; // from here: whether the batch sets normals itself
}

void StateTracker::end()
{
    if (!mInBegin) return;
    mInBegin = false;
    if (!mBatch.hasNormals) {
        // A glNormal inside the batch: the vertices before it count as well. None: the
        // vertices carry no normal of their own (see currentNormalCounts).
        mBatch.hasNormals = mNormalFresh;
        for (TrackedVertex& v : mBatch.vertices) v.hasNormal = mNormalFresh;
    }
    emit(std::move(mBatch));
    mBatch = TrackedBatch();
}

bool StateTracker::currentNormalCounts() const
{
    // Unlit, the program's picture never sees the current normal, and one set for an earlier
    // object is no normal of this one: the styles then take the geometry's own. A list being
    // compiled is lit or not where it is called: its normals count as before.
    return mNormalSet && (mNormalFresh || mAttrib.lighting || mCompiling);
}

void StateTracker::emit(TrackedBatch&& batch)
{
    mNormalFresh = false;
    if (keep(batch)) {
        indexBatch(batch);
        mFrameBatches.push_back(std::move(batch));
    }
    else recycle(std::move(batch.vertices));
}

// Completes a batch with the state of its draw; false when the frame does not keep it.
bool StateTracker::keep(TrackedBatch& batch)
{
    if (!isPolygonMode(batch.mode)) {
        otherDraw();
        return false;
    }
    if (batch.vertices.empty()) return false;
    if (mCompiling && mListDepth == 0) { // a called list's batches: see runCalls
        mCompiled.inherits.push_back({!mListSetsColor, !mListSetsNormal, !mListSetsTexCoord});
        mCompiled.batches.push_back(batch);
        ListItem item;
        item.batch = int(mCompiled.batches.size()) - 1;
        mCompiled.items.push_back(std::move(item));
        if (!mCompileAndExecute) return false;
    }
    batch.modelview = mMatrices.modelview();
    batch.projection = mMatrices.projection();
    batch.materialId = currentMaterialId();
    const AttribState& a = mAttrib;
    const glm::vec4 current = batch.vertices.front().color; // before lighting replaces it
    float ambientShare = -1.0f, diffuseShare = -1.0f;
    glm::vec3 shadowTint(1.0f);
    if (mProgramLighting) {
        if (a.lighting) FixedLighting::lightBatch(a, batch);
        if (a.flatShade) FixedLighting::flattenBatch(batch);
    }
    // What the program's picture shows: lit surfaces take the material's colour in the light
    // on their lit side, plus the light the material emits, clamped per channel as GL clamps
    // (a track whose materials are mostly emission, as torcs's are, was far too dark).
    else if (a.lighting) {
        // One pass over the vertices: the material's colour (or the vertex's), lit.
        const glm::vec3 at =
            glm::vec3(batch.modelview * glm::vec4(batch.vertices.front().position, 1.0f));
        const size_t key = keyLight();
        const glm::vec4 front =
            FixedLighting::colourLitSides(a, batch, FixedLighting::litSideLight(a, at, key));
        // The shares are the front's (a back's colours differ in hue, not in how GL lights).
        ambientShare = FixedLighting::ambientShare(a, current, front);
        shadowTint = FixedLighting::shadowTint(a, current, front);
        diffuseShare = FixedLighting::diffuseShare(a, current, front, key);
        addEvenSpecular(batch);
    }
    batch.is3D = styles::perspective(batch.projection) || (a.depthTest && a.depthMask);
    batch.clockwise = a.frontFace == GL_CW;
    batch.culled = culledWinding();
    batch.texture = detailTexture();
    replacedByTexture(batch);
    // Blending by alpha where every alpha is 1 changes no pixel: the program blends all its
    // drawing (neverball does), and such surfaces are opaque ones (with outlines); so does a
    // pass over a held surface (merged below).
    const bool blends = translucent();
    const bool opaque = (blends || a.alphaTest) && opaqueAlpha(batch);
    if (mHolding) {
        // Inside a list the driver draws itself (not masked by the compositor) nothing is
        // held: the style would draw it a second time over the program's own.
        batch.held = mHoldingList > 0 || (mPassingList == 0 && wouldHold(batch.mode));
        // A blended pass over geometry already held (a shine, light or detail stage, left
        // for its blending and asked about by the compositor) is that object's: merged into
        // it, not drawn or styled again. Not so a layer blended by an alpha that is not 1
        // everywhere (water or paint laid over the ground through a texture's alpha, a fog
        // stage), nor one the program lifts off the surface with a polygon offset (a decal:
        // neverball's start arrow on its floor tile): their pictures are their own, held as
        // objects drawn over what they cover.
        const bool own = blends && !opaque;
        const bool lifted = a.polygonOffsetFill && (a.offsetFactor < 0.0f || a.offsetUnits < 0.0f);
        if (blending() && !own && !(blends && lifted) && repeatsHeld(batch, blends)) {
            if (mWatch.on) ++mWatch.repeated;
            else ++mMergedPasses;
            return false;
        }
        if (mWatch.on) ++mWatch.others;
        if (!batch.held) return false; // the compositor keeps only what it re-draws
    }
    if (a.lighting) litBy(batch.lights);
    else batch.lights.count = 0;
    batch.normals = a.normalize ? GL_NORMALIZE : a.rescaleNormal ? GL_RESCALE_NORMAL : 0;
    batch.lights.ambientShare = ambientShare;
    batch.lights.diffuseShare = diffuseShare;
    batch.lights.shadowTint = shadowTint;
    if (batch.texture == 0) {
        batch.generated = generatedTexture();
        bakeObjectLinear(batch);
    }
    // Without GL lighting a lightmap is the surface's light (the styles' L·n).
    batch.lightmap = mLightUnit >= 0 && !a.lighting ? unitTexture(mLightUnit) : 0;
    layerEffects(batch);
    batch.translucent = blends && !opaque;
    batch.depthWrite = a.depthMask;
    // A test at GL_ALWAYS hides nothing: drawn as without the test, but it writes its depth
    // (a program may reset its depth buffer with such a quad instead of glClear).
    batch.depthTest = a.depthTest && a.depthFunc != GL_ALWAYS;
    batch.depthAlways = a.depthTest && a.depthFunc == GL_ALWAYS;
    batch.depthFunc = a.depthFunc;
    // The styles test their alpha (the program's, its texture modulating) as it would. A test
    // that no alpha of the draw can fail cuts nothing out: some programs leave it on for all
    // their drawing (extremetuxracer does), and such surfaces are opaque ones (with outlines).
    const bool cuts = a.alphaTest && !(opaque && passesAlphaOne(a.alphaFunc, a.alphaRef));
    batch.alphaFunc = cuts ? a.alphaFunc : GL_ALWAYS;
    batch.alphaRef = a.alphaRef;
    if (cuts && batch.texture != 0) {
        batch.cutFeature = mTextures.cutFeature(styles::textureName(batch.texture));
        // A texture the test keeps whole, faded by its colours' alpha below what the test
        // keeps of it: a surface fading as a whole, not a shape (its cut not known).
        if (batch.cutFeature == kKeptWhole) {
            for (const TrackedVertex& v : batch.vertices) {
                if (!(v.color.a >= 0.5f)) {
                    batch.cutFeature = 0.0f;
                    break;
                }
            }
        }
    }
    batch.depthOnly = a.colorMaskNone();
    // Decals: the styles pull the surface towards the eye by the program's offset.
    batch.offsetFactor = a.polygonOffsetFill ? a.offsetFactor : 0.0f;
    batch.offsetUnits = a.polygonOffsetFill ? a.offsetUnits : 0.0f;
    batch.fog = {a.fog ? a.fogMode : 0, a.fogStart, a.fogEnd, a.fogDensity, a.fogColour};
    batch.viewport = a.viewport;
    applyTextureMatrices(batch);
    // Hashed now, while the vertices are in the cache; reconstruction looks its mesh up by it.
    batch.contentHash =
        reconstruct::hashVertices(batch.vertices.data(), batch.vertices.size(),
                                  reconstruct::assemblyMode(batch.mode, batch.clockwise,
                                                            batch.quadCut));
    return true;
}

void StateTracker::setEnabled(GLenum cap, bool on)
{
    AttribState& a = mAttrib;
    switch (cap) {
    case GL_LIGHTING: a.lighting = on; break;
    case GL_COLOR_MATERIAL: a.colorMaterial = on; break;
    case GL_NORMALIZE: a.normalize = on; break;
    case GL_RESCALE_NORMAL: a.rescaleNormal = on; break;
    case GL_DEPTH_TEST: a.depthTest = on; break;
    case GL_SCISSOR_TEST: a.scissorTest = on; break;
    case GL_TEXTURE_2D:
        if (mActiveUnit == 0) {
            a.texture2D = on;
            break;
        }
        [[fallthrough]];
    case GL_TEXTURE_1D:
    case GL_TEXTURE_3D:
    case GL_TEXTURE_CUBE_MAP:
        // Another unit, or another target: a draw textured by one unit's 2D texture alone is
        // styled with it (surfaceUnit); several units are multitexturing.
        if (on) a.textureUnits |= 1u << std::min(mActiveUnit, 31);
        else a.textureUnits &= ~(1u << std::min(mActiveUnit, 31));
        if (cap == GL_TEXTURE_CUBE_MAP) {
            if (on) a.cubeUnits |= 1u << std::min(mActiveUnit, 31);
            else a.cubeUnits &= ~(1u << std::min(mActiveUnit, 31));
        }
        if (cap == GL_TEXTURE_2D) {
            if (on) a.texture2DUnits |= 1u << std::min(mActiveUnit, 31);
            else a.texture2DUnits &= ~(1u << std::min(mActiveUnit, 31));
        }
        break;
    case GL_TEXTURE_GEN_S:
    case GL_TEXTURE_GEN_T:
    case GL_TEXTURE_GEN_R:
    case GL_TEXTURE_GEN_Q:
        // Each coordinate of each unit on its own: a program that turns sphere mapping off
        // again draws plain textures again.
        if (mActiveUnit < 8) {
            const uint32_t bit = 1u << (4 * mActiveUnit + int(cap - GL_TEXTURE_GEN_S));
            a.texGen = on ? a.texGen | bit : a.texGen & ~bit;
        }
        break;
    case GL_BLEND: a.blend = on; break;
    case GL_FOG: a.fog = on; break;
    case GL_POLYGON_OFFSET_FILL: a.polygonOffsetFill = on; break;
    case GL_CULL_FACE: a.cullFace = on; break;
    case GL_ALPHA_TEST: a.alphaTest = on; break;
    case GL_STENCIL_TEST: a.stencilTest = on; break;
    case GL_LIGHT0:
    case GL_LIGHT1:
    case GL_LIGHT2:
    case GL_LIGHT3:
    case GL_LIGHT4:
    case GL_LIGHT5:
    case GL_LIGHT6:
    case GL_LIGHT7: {
        const uint8_t bit = uint8_t(1u << (cap - GL_LIGHT0));
        a.lightsOn = on ? uint8_t(a.lightsOn | bit) : uint8_t(a.lightsOn & ~bit);
        break;
    }
    case GL_VERTEX_PROGRAM_ARB: a.vertexProgram = on; break;
    case GL_FRAGMENT_PROGRAM_ARB: a.fragmentProgram = on; break;
    default: break;
    }
}

void StateTracker::texImage2D(GLenum target, GLint level, GLint internalFormat,
                              GLsizei width, GLsizei height, GLenum format, GLenum type,
                              const void* pixels)
{
    if (target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z &&
        level == 0 && size_t(mActiveUnit) < mUnitCubeTextures.size()) {
        // A face of the bound cube map: its mean joins the others' (an environment the
        // styles drop keeps its tint).
        mTextures.cubeFace(mUnitCubeTextures[size_t(mActiveUnit)],
                           int(target - GL_TEXTURE_CUBE_MAP_POSITIVE_X), width, height, format,
                           type, pixels, mImageBytes);
        return;
    }
    if (target != GL_TEXTURE_2D || level != 0 || size_t(mActiveUnit) >= mUnitTextures.size()) {
        return;
    }
    mTextures.image2D(mUnitTextures[size_t(mActiveUnit)], internalFormat, width, height, format,
                      type, pixels, mImageBytes);
}

void StateTracker::texStorage2D(GLenum target, GLint level, GLenum internalFormat, bool empty)
{
    if (target != GL_TEXTURE_2D || level != 0 || size_t(mActiveUnit) >= mUnitTextures.size()) {
        return;
    }
    mTextures.storage2D(mUnitTextures[size_t(mActiveUnit)], internalFormat, empty);
}

void StateTracker::texSubImage2D(GLenum target, GLint level, GLint x, GLint y, GLsizei width,
                                 GLsizei height, GLenum format, GLenum type, const void* pixels)
{
    if (target != GL_TEXTURE_2D || level != 0 || size_t(mActiveUnit) >= mUnitTextures.size()) {
        return;
    }
    mTextures.subImage2D(mUnitTextures[size_t(mActiveUnit)], x, y, width, height, format, type,
                         pixels, mImageBytes);
}

void StateTracker::texCopiedInto(GLenum target, GLint level)
{
    if (target != GL_TEXTURE_2D || level != 0 || size_t(mActiveUnit) >= mUnitTextures.size()) {
        return;
    }
    mTextures.overwritten(mUnitTextures[size_t(mActiveUnit)]);
}

} // namespace nprgl
