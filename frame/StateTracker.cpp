#include "frame/StateTracker.h"

#include "frame/TrackerDispatch.h"
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

namespace {

// The reason for a list left for the blending inside it.
constexpr const char* kListBlendsLeft = "display lists that blend inside other than by "
                                        "GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA (shadows, effects)";

// Blending that changes a pixel: GL_BLEND on, with functions other than GL_ONE, GL_ZERO (the
// defaults, which replace what is behind: trigger-rally leaves GL_BLEND on all frame and draws
// its opaque parts so).
bool changesPixels(bool blend, GLenum src, GLenum dst)
{
    return blend && !(src == GL_ONE && dst == GL_ZERO);
}

// Blending by the fragment's alpha: a translucent surface, which the styles draw after the
// opaque scene with the program's blending.
bool byAlpha(bool blend, GLenum src, GLenum dst)
{
    return blend && src == GL_SRC_ALPHA && dst == GL_ONE_MINUS_SRC_ALPHA;
}

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

GLuint listId(GLenum type, const uint8_t* p, GLsizei i)
{
    switch (type) {
    case GL_BYTE: return GLuint(GLint(reinterpret_cast<const int8_t*>(p)[i]));
    case GL_UNSIGNED_BYTE: return p[i];
    case GL_SHORT: { int16_t v; std::memcpy(&v, p + 2 * i, 2); return GLuint(GLint(v)); }
    case GL_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, p + 2 * i, 2); return v; }
    case GL_INT:
    case GL_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, p + 4 * i, 4); return v; }
    case GL_FLOAT: { float v; std::memcpy(&v, p + 4 * i, 4); return GLuint(v); }
    case GL_2_BYTES: return GLuint(p[2 * i]) * 256 + p[2 * i + 1];
    case GL_3_BYTES: return (GLuint(p[3 * i]) << 16) + (GLuint(p[3 * i + 1]) << 8) + p[3 * i + 2];
    case GL_4_BYTES:
        return (GLuint(p[4 * i]) << 24) + (GLuint(p[4 * i + 1]) << 16) +
               (GLuint(p[4 * i + 2]) << 8) + p[4 * i + 3];
    default: return 0;
    }
}

bool isPolygonMode(GLenum mode) { return mode >= GL_TRIANGLES && mode <= GL_POLYGON; }

// Component i of an array element (unaligned).
template <typename T>
T load(const uint8_t* p, int i)
{
    T v;
    std::memcpy(&v, p + sizeof(T) * size_t(i), sizeof(T));
    return v;
}

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

bool StateTracker::wouldHold(GLenum mode) const
{
    return mHolding && isPolygonMode(mode) && !mCompiling && mRenderMode == GL_RENDER &&
           is3D() && !unstylableState();
}

bool StateTracker::is3D() const
{
    // A perspective view, or a depth-tested one that writes depth. Orthographic drawing
    // that writes no depth is 2D even with the depth test on (ioquake3 draws its HUD so).
    const AttribState& a = mAttrib;
    return styles::perspective(mMatrices.projection()) || (a.depthTest && a.depthMask);
}

const char* StateTracker::unstylableState() const
{
    // Drawn now and kept in the list: the list's later calls are styled, this first one not.
    if (mCompiling && mCompileAndExecute) return "glNewList(GL_COMPILE_AND_EXECUTE)";
    if (leftByRule()) return "a rule of the program's configuration (leave_texture, leave_state)";
    // The program's shaders decide colour and position; a style would draw something else.
    if (ownShaders()) return "the program's own shaders";
    if (blending() && !translucent()) {
        return "blending other than GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA (additive, effects)";
    }
    if (const char* why = pipelineLimit()) return why;
    // Generated coordinates on unit 0 (sphere maps, reflections) are styled, the generated
    // texture dropped; on other units they belong to multitexturing.
    if (surfaceUnit() < 0) return multitexturing();
    return nullptr;
}

bool StateTracker::ownShaders() const
{
    const AttribState& a = mAttrib;
    return mProgram != 0 || a.vertexProgram || a.fragmentProgram;
}

const char* StateTracker::pipelineLimit() const
{
    if (mDrawingData) return kDrawingDataWhy;
    const AttribState& a = mAttrib;
    if (a.stencilTest) return "the stencil test";
    // A side's mode matters only where that side is drawn: programs set lines for the back
    // faces they cull (foobillardplus's filled table).
    const bool frontDrawn = !a.cullFace || a.cullMode == GL_BACK;
    const bool backDrawn = !a.cullFace || a.cullMode == GL_FRONT;
    if ((!a.fillFront && frontDrawn) || (!a.fillBack && backDrawn)) {
        return "glPolygonMode lines or points";
    }
    // A depth-only pass (no colour channel) is held: the styles supply its depth. So is one
    // that masks only alpha (the picture is all its own; the styles keep alpha as masked).
    if (!a.colorMaskRgb() && !a.colorMaskNone()) return "a partial colour mask";
    // The styles run inside one more glPushAttrib/glPushClientAttrib: a full stack would
    // leave the held scene undrawn.
    if (int(mAttribs.depth()) >= mMaxAttribDepth || mClientDepth >= mMaxClientDepth) {
        return "a full attribute stack";
    }
    return nullptr;
}

bool StateTracker::mayLayer(GLenum mode) const
{
    // Left for its blending (or its texture layers) only: the other reasons to leave a draw
    // (shaders, stencil, lines, masks, rules, a full stack) keep it the program's whatever
    // it draws over.
    const AttribState& a = mAttrib;
    if (!mHolding || !isPolygonMode(mode) || mCompiling || mRenderMode != GL_RENDER ||
        !is3D() || !blending() || !a.colorMaskRgb()) {
        return false;
    }
    if (ownShaders() || pipelineLimit() || leftByRule()) return false;
    return unstylableState() != nullptr;
}

bool StateTracker::mayLayerList(GLuint list) const
{
    bool anyBatch = false;
    return mayLayer(GL_TRIANGLES) && listHoldable(list, anyBatch) && anyBatch;
}

bool StateTracker::repeatedAll()
{
    const bool all = mWatch.repeated > 0 && mWatch.others == 0;
    mWatch = {};
    return all;
}

bool StateTracker::leftByRule() const
{
    if (const uint32_t states = mRules.states) {
        const AttribState& a = mAttrib;
        const bool backdrop = !a.depthTest && styles::perspective(mMatrices.projection());
        if (((states & kLeaveTranslucent) && translucent()) ||
            ((states & kLeaveCutout) && a.alphaTest) ||
            ((states & kLeaveDecal) && a.polygonOffsetFill) ||
            ((states & kLeaveBackdrop) && backdrop)) {
            return true;
        }
    }
    return !mRules.textures.empty() && detailTexture() != 0 &&
           mRules.leavesTexture(textureHash(detailTexture()));
}

GLenum StateTracker::culledWinding() const
{
    // Batches are assembled with the program's front faces counter-clockwise
    // (TrackedBatch::clockwise): its back faces are the clockwise ones there.
    const AttribState& a = mAttrib;
    if (!a.cullFace) return 0;
    if (a.cullMode == GL_FRONT_AND_BACK) return GL_FRONT_AND_BACK;
    return a.cullMode == GL_FRONT ? GL_CCW : GL_CW;
}

// What a pass over a batch shares with it, hashed: mode, size, culling, matrices and three of
// its positions (the rest are compared on a match). Constant time whatever the batch's size.
uint64_t StateTracker::passKey(const TrackedBatch& batch)
{
    struct Key {
        GLenum mode, culled;
        uint64_t count;
        glm::mat4 modelview, projection;
        glm::vec3 first, middle, last;
    } key{};
    std::memset(&key, 0, sizeof key); // no padding bytes of chance in the hash
    key.mode = batch.mode;
    key.culled = batch.culled;
    key.count = batch.vertices.size();
    key.modelview = batch.modelview;
    key.projection = batch.projection;
    if (!batch.vertices.empty()) {
        key.first = batch.vertices.front().position;
        key.middle = batch.vertices[batch.vertices.size() / 2].position;
        key.last = batch.vertices.back().position;
    }
    return XXH3_64bits(&key, sizeof key);
}

void StateTracker::indexBatch(const TrackedBatch& batch)
{
    // A depth-only pass shows nothing a layer could merge into.
    if (!batch.depthOnly) mPassIndex.emplace(passKey(batch), uint32_t(mFrameBatches.size()));
}

bool StateTracker::repeatsHeld(const TrackedBatch& batch, bool layer) const
{
    // Passes may come right after their surface (ioquake3 draws a shader's stages so) or
    // after the whole scene (a lightmap pass over a world): any batch of the frame, found by
    // its key.
    auto [from, to] = mPassIndex.equal_range(passKey(batch));
    for (auto it = from; it != to; ++it) {
        const TrackedBatch& base = mFrameBatches[it->second];
        if ((layer && base.translucent) || base.mode != batch.mode ||
            base.vertices.size() != batch.vertices.size() || base.culled != batch.culled ||
            std::memcmp(&base.modelview, &batch.modelview, sizeof(glm::mat4)) != 0 ||
            std::memcmp(&base.projection, &batch.projection, sizeof(glm::mat4)) != 0) {
            continue;
        }
        bool same = true;
        for (size_t v = 0; v < batch.vertices.size() && same; ++v) {
            same = std::memcmp(&base.vertices[v].position, &batch.vertices[v].position,
                               sizeof(glm::vec3)) == 0;
        }
        if (same) return true;
    }
    return false;
}

const char* StateTracker::multitexturing() const
{
    uint32_t layers = 0;
    if (texturedUnits(layers) == 0) {
        return "texture combiners or additions with no plain texture (GL_COMBINE, GL_ADD)";
    }
    return "a 1D, 3D or cube-map texture on the surface (the styles draw 2D textures)";
}

uint32_t StateTracker::texturedUnits(uint32_t& layers) const
{
    const AttribState& a = mAttrib;
    const uint32_t textured = (a.textureUnits | (a.texture2D ? 1u : 0u)) & 0xFFu;
    // The surface's texture is on the lowest unit that applies a texture of its own, on
    // coordinates of its own, the plain way (GL_MODULATE, GL_REPLACE, GL_DECAL). The other
    // units layer light or effects over it: lightmaps and shadows through combiners or
    // additions, environment maps on generated coordinates.
    uint32_t plain = 0;
    const uint32_t depth = depthUnits();
    for (int u = 0; u < 8; ++u) {
        const GLenum mode = a.envMode[size_t(u)];
        const bool ownCoordinates = ((a.texGen >> (4 * u)) & 0x3u) != 0x3u;
        const bool applies = (mode == GL_MODULATE || mode == GL_REPLACE || mode == GL_DECAL) &&
                             !(depth & (1u << u));
        if ((textured & (1u << u)) && ownCoordinates && applies) plain |= 1u << u;
    }
    // Only the first textured unit may be a generated or combined one on its own (a sphere
    // map alone is styled without it; a combiner alone is not the surface's texture).
    const uint32_t base = plain ? plain & (~plain + 1u) : 0u;
    layers = textured & ~base;
    return base;
}

uint32_t StateTracker::depthUnits() const
{
    const AttribState& a = mAttrib;
    uint32_t units = 0;
    for (int u = 0; u < 8; ++u) {
        // The unit's 2D texture is the one it applies (a cube map or another target wins).
        const bool twoD = u == 0 ? a.texture2D && !(a.textureUnits & 1u)
                                 : ((a.texture2DUnits & ~a.cubeUnits) >> u) & 1u;
        if (twoD && mTextures.depth(mUnitTextures[size_t(u)])) units |= 1u << u;
    }
    return units;
}

int StateTracker::surfaceUnit() const
{
    const AttribState& a = mAttrib;
    uint32_t layers = 0;
    const uint32_t base = texturedUnits(layers);
    if (base == 0) {
        // No plain texture: untextured, or a reflective surface: a unit on generated
        // coordinates (an environment map, styled without its texture) under combined or
        // added layers (shadows, fades; not drawn). Combiners alone are the surface's colour
        // computed in ways the styles cannot follow.
        // A shadow map alone leaves the surface untextured.
        const uint32_t textured =
            (a.textureUnits | (a.texture2D ? 1u : 0u)) & 0xFFu & ~depthUnits();
        if (textured == 0) return 0;
        uint32_t generated = 0;
        for (int u = 0; u < 8; ++u) {
            if ((textured & (1u << u)) && ((a.texGen >> (4 * u)) & 0x3u) == 0x3u) {
                generated |= 1u << u;
            }
        }
        if (generated == 0) return -1;
        for (int u = 0; u < 8; ++u) {
            const GLenum mode = a.envMode[size_t(u)];
            const bool layer = mode == GL_COMBINE || mode == GL_ADD;
            if ((textured & ~generated & (1u << u)) && !layer) return -1;
        }
        return std::countr_zero(generated);
    }
    const int u = std::countr_zero(base);
    // The surface's texture must be a 2D one (the styles draw 2D textures).
    if (u == 0) return (a.textureUnits & 1u) == 0 ? 0 : -1;
    return u < 8 && (a.texture2DUnits & base) != 0 ? u : -1;
}

uint32_t StateTracker::droppedLayers() const
{
    uint32_t layers = 0;
    texturedUnits(layers);
    const int surface = surfaceUnit();
    if (surface < 0) return 0;
    // A surface on generated coordinates comes from among the layers (texturedUnits finds no
    // plain one): it is drawn, not dropped.
    layers &= ~(1u << surface);
    const int light = mAttrib.lighting ? -1 : lightUnit();
    return light < 0 ? layers : layers & ~(1u << light);
}

int StateTracker::lightUnit() const
{
    const AttribState& a = mAttrib;
    uint32_t layers = 0;
    if (texturedUnits(layers) == 0) return -1;
    layers &= ~depthUnits();
    for (int u = 0; u < 8; ++u) {
        if (!(layers & (1u << u)) || a.envMode[size_t(u)] != GL_MODULATE) continue;
        if (((a.texGen >> (4 * u)) & 0x3u) == 0x3u) continue;
        const bool twoD = u == 0 ? a.texture2D : (a.texture2DUnits & (1u << u)) != 0;
        return twoD ? u : -1;
    }
    return -1;
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

void StateTracker::followSurfaceUnit()
{
    const int u = std::max(surfaceUnit(), 0);
    if (u != mSurfaceUnit) {
        mUnitTexcoords[size_t(mSurfaceUnit)] = mCurrent.texcoord;
        mSurfaceUnit = u;
        mCurrent.texcoord = mUnitTexcoords[size_t(u)];
    }
    // The lightmap's coordinates are a copy: every unit's own are in mUnitTexcoords (or, for
    // the surface's unit, mCurrent.texcoord).
    mLightUnit = lightUnit();
    if (mLightUnit >= 0) mCurrent.lightcoord = mUnitTexcoords[size_t(mLightUnit)];
}

void StateTracker::texGen(GLenum coord, GLenum pname, const double* values, size_t count)
{
    if (coord < GL_S || coord > GL_Q || mActiveUnit >= 8) return;
    const uint32_t c = coord - GL_S;
    AttribState& a = mAttrib;
    if (pname == GL_TEXTURE_GEN_MODE && count == 1) {
        const GLenum mode = enumOf(values[0]);
        if (mode != GL_SPHERE_MAP && mode != GL_OBJECT_LINEAR && mode != GL_EYE_LINEAR &&
            mode != GL_NORMAL_MAP && mode != GL_REFLECTION_MAP) {
            return; // the driver refuses it (GL_INVALID_ENUM)
        }
        a.texGenMode[4 * mActiveUnit + c] = mode;
        return;
    }
    if (c > 1 || count != 4) return; // R and Q planes: only S and T map a 2D texture
    const glm::vec4 plane{float(values[0]), float(values[1]), float(values[2]), float(values[3])};
    if (pname == GL_OBJECT_PLANE) {
        a.objectPlane[2 * mActiveUnit + c] = plane;
    } else if (pname == GL_EYE_PLANE) {
        // GL keeps p M^-1 (M: the modelview at the call), so that p · eye position holds.
        a.eyePlane[2 * mActiveUnit + c] = plane * glm::inverse(mMatrices.modelview());
    }
}

styles::GeneratedTexture StateTracker::generatedTexture() const
{
    // The surface unit's 2D texture on S and T generated by a mode the styles can follow: a
    // reflection or a projection they may show as detail (their parameter).
    const AttribState& a = mAttrib;
    const int u = surfaceUnit();
    styles::GeneratedTexture g;
    if (u < 0 || u >= 8 || ((a.texGen >> (4 * u)) & 0x3u) != 0x3u) return g;
    for (int c = 0; c < 2; ++c) {
        const GLenum mode = a.texGenMode[size_t(4 * u + c)];
        if (mode != GL_SPHERE_MAP && mode != GL_OBJECT_LINEAR && mode != GL_EYE_LINEAR) {
            return {}; // cube-map coordinates (normal, reflection map): a 2D map cannot take them
        }
        g.mode[c] = mode;
        g.plane[c] = mode == GL_OBJECT_LINEAR ? a.objectPlane[size_t(2 * u + c)]
                                              : a.eyePlane[size_t(2 * u + c)];
    }
    g.texture = unitTexture(u);
    if (g.texture == 0) return {};
    g.matrix = mMatrices.texture(u);
    if (const glm::vec3* mean = mTextures.mean(mUnitTextures[size_t(u)])) g.mean = *mean;
    return g;
}

GLuint StateTracker::detailTexture() const
{
    // A texture on generated coordinates (an environment or reflection map) is not the
    // surface's own: the styles draw the surface without it.
    const AttribState& a = mAttrib;
    const int u = surfaceUnit();
    if (u < 0 || ((a.texGen >> (4 * u)) & 0xFu) != 0) return 0;
    if (depthUnits() & (1u << u)) return 0; // a shadow map alone on unit 0
    return unitTexture(u);
}

GLuint StateTracker::unitTexture(int unit) const
{
    if (unit == 0) return mAttrib.texture2D ? sceneTexture(mBoundTexture) : 0;
    return sceneTexture(mUnitTextures[size_t(unit)]);
}

void StateTracker::bakeObjectLinear(TrackedBatch& batch) const
{
    // Coordinates on object planes are fixed to the vertices like the program's own: made
    // here, per batch, they stay right when batches with planes of their own (a terrain's
    // tiles, each its texture and its planes) are welded into one object.
    styles::GeneratedTexture& g = batch.generated;
    if (g.texture == 0 || g.mode[0] != GL_OBJECT_LINEAR || g.mode[1] != GL_OBJECT_LINEAR) return;
    for (TrackedVertex& v : batch.vertices) {
        const glm::vec4 p(v.position, 1.0f);
        v.texcoord = {glm::dot(g.plane[0], p), glm::dot(g.plane[1], p)};
    }
    batch.texture = g.texture; // the texture matrix follows (applyTextureMatrices)
    g = {};
}

void StateTracker::applyTextureMatrices(TrackedBatch& batch) const
{
    // The texture and lightmap coordinates as the units' texture matrices move them (a
    // scrolled or scaled texture); one pass, and none where both are the identity.
    static const glm::mat4 kIdentity(1.0f);
    const int u = surfaceUnit();
    const glm::mat4& surface = u >= 0 ? mMatrices.texture(u) : kIdentity;
    const glm::mat4& light = mLightUnit >= 0 ? mMatrices.texture(mLightUnit) : kIdentity;
    const bool moveSurface = surface != kIdentity, moveLight = light != kIdentity;
    if (!moveSurface && !moveLight) return;
    auto apply = [](const glm::mat4& m, glm::vec2& st) {
        const glm::vec4 t = m * glm::vec4(st, 0.0f, 1.0f);
        st = t.w != 0.0f ? glm::vec2(t) / t.w : glm::vec2(t);
    };
    for (TrackedVertex& v : batch.vertices) {
        if (moveSurface) apply(surface, v.texcoord);
        if (moveLight) apply(light, v.lightcoord);
    }
}

GLuint StateTracker::sceneTexture(GLuint name) const
{
    // The default texture, once it has an image (enabled without one, GL draws untextured:
    // so do the styles). GL has one default 2D texture, whichever unit binds it.
    return name == 0 && mTextures.defaultImage() ? styles::kDefaultTexture : name;
}

bool StateTracker::wouldHoldList(GLuint list) const
{
    bool anyBatch = false;
    return wouldHold(GL_TRIANGLES) && listHoldable(list, anyBatch) && anyBatch &&
           !listDraws(list).blendsLeft;
}

const char* StateTracker::listUnstylable(GLuint list) const
{
    if (const char* why = unstylableState()) return why;
    bool anyBatch = false;
    if (!listHoldable(list, anyBatch)) {
        return "display lists that also draw lines, points, bitmaps or pixels";
    }
    if (anyBatch && listDraws(list).blendsLeft) return kListBlendsLeft;
    return nullptr; // holdable, or no polygons at all (nothing to count)
}

const char* StateTracker::listsUnstylable(GLsizei n, GLenum type, const void* lists) const
{
    const uint8_t* p = static_cast<const uint8_t*>(lists);
    // 2D drawing (text from font lists, most often) is not counted: no walk over its lists.
    if (!p || n <= 0 || !is3D()) return nullptr;
    bool anyBatch = false, holdable = true, blendsLeft = false;
    for (GLsizei i = 0; i < std::min<GLsizei>(n, 4096); ++i) {
        const GLuint list = mListBase + listId(type, p, i);
        bool ignored = false;
        holdable = listHoldable(list, ignored) && holdable;
        const ListDraws drawn = listDraws(list); // its batches and those of the lists it calls
        anyBatch = anyBatch || drawn.textured + drawn.untextured > 0;
        blendsLeft = blendsLeft || drawn.blendsLeft;
    }
    if (!anyBatch) return nullptr;
    if (const char* why = unstylableState()) return why;
    if (n > 4096) return "glCallLists of more than 4096 lists";
    if (!holdable) return "display lists that also draw lines, points, bitmaps or pixels";
    return blendsLeft ? kListBlendsLeft : nullptr;
}

bool StateTracker::listHoldable(GLuint list, bool& anyBatch) const
{
    // Breadth-first over the lists it calls; cycles and depth bounded like the driver's.
    std::vector<GLuint> pending{list};
    for (size_t i = 0; i < pending.size() && i < 64; ++i) {
        auto it = mLists.find(pending[i]);
        if (it == mLists.end()) continue;
        if (it->second.otherDraws) return false;
        anyBatch = anyBatch || !it->second.batches.empty();
        pending.insert(pending.end(), it->second.calls.begin(), it->second.calls.end());
    }
    return true;
}

void StateTracker::light(GLenum light, GLenum pname, const float* v)
{
    if (light < GL_LIGHT0 || light >= GL_LIGHT0 + 8 || !v) return;
    const size_t i = light - GL_LIGHT0;
    if (pname == GL_POSITION) {
        // GL stores the position in eye space, transformed by the modelview of the call.
        mAttrib.lightPosition[i] = mMatrices.modelview() * glm::vec4(v[0], v[1], v[2], v[3]);
    } else if (pname == GL_DIFFUSE) {
        mAttrib.lightDiffuse[i] = glm::vec3(v[0], v[1], v[2]);
    } else if (pname == GL_SPECULAR) {
        mAttrib.lightSpecular[i] = glm::vec3(v[0], v[1], v[2]);
    } else if (pname == GL_AMBIENT) {
        mAttrib.lightAmbient[i] = glm::vec3(v[0], v[1], v[2]);
    } else if (pname == GL_SPOT_DIRECTION) {
        // Eye space too, by the modelview's upper 3x3.
        mAttrib.spotDirection[i] = glm::mat3(mMatrices.modelview()) * glm::vec3(v[0], v[1], v[2]);
    } else if (pname == GL_SPOT_CUTOFF) {
        mAttrib.spotCutoff[i] = v[0];
    } else if (pname == GL_SPOT_EXPONENT) {
        mAttrib.spotExponent[i] = v[0];
    } else if (pname == GL_CONSTANT_ATTENUATION) {
        mAttrib.attenuation[i].x = v[0];
    } else if (pname == GL_LINEAR_ATTENUATION) {
        mAttrib.attenuation[i].y = v[0];
    } else if (pname == GL_QUADRATIC_ATTENUATION) {
        mAttrib.attenuation[i].z = v[0];
    }
}

void StateTracker::litBy(styles::SceneLights& out) const
{
    // The enabled lights, the brightest (keyLight) first, each weighted by its diffuse
    // brightness against the brightest's: a surface facing the brightest light is fully lit,
    // as in GL, and a dimmer fill light adds its part.
    const AttribState& a = mAttrib;
    out.count = 0;
    const size_t key = keyLight();
    float top = 0.0f;
    for (size_t k = 0; k < 8; ++k) {
        const size_t i = k == 0 ? key : (k <= key ? k - 1 : k);
        if (!(a.lightsOn & (1u << i))) continue;
        styles::SceneLights::Light& l = out.lights[out.count++];
        // As the shader takes them, without branches: a far light is not attenuated, and a
        // light that is no spot keeps SceneLights' cutoff of -2 and an exponent of 0.
        l.position = a.lightPosition[i];
        const bool positional = l.position.w != 0.0f;
        const bool spot = positional && a.spotCutoff[i] < 180.0f;
        const float length = glm::length(a.spotDirection[i]);
        l.spotDirection = spot && length > 1e-12f ? a.spotDirection[i] / length
                                                  : glm::vec3(0.0f, 0.0f, -1.0f);
        l.spotCosCutoff = spot ? std::cos(glm::radians(std::max(a.spotCutoff[i], 0.0f))) : -2.0f;
        l.falloff = positional ? glm::vec4(a.attenuation[i], spot ? a.spotExponent[i] : 0.0f)
                               : glm::vec4(1.0f, 0.0f, 0.0f, 0.0f);
        l.weight = glm::dot(glm::max(a.lightDiffuse[i], glm::vec3(0.0f)),
                            glm::vec3(0.299f, 0.587f, 0.114f));
        top = std::max(top, l.weight);
    }
    for (uint32_t k = 0; k < out.count; ++k) {
        styles::SceneLights::Light& l = out.lights[k];
        l.weight = top > 1e-6f ? l.weight / top : 1.0f;
    }
    // The highlight GL draws: the brightest light's. Under GL_COLOR_MATERIAL's specular mode
    // the colour is per vertex, which the styles' one highlight colour cannot follow: none.
    const bool colourSpecular = a.frontColorMaterial() && a.colorMaterialMode == GL_SPECULAR;
    out.shine = out.count > 0 && !colourSpecular
                    ? glm::clamp(glm::max(a.lightSpecular[key], 0.0f) * a.material.specular,
                                 0.0f, 1.0f)
                    : glm::vec3(0.0f);
    out.shininess = std::clamp(a.material.shininess, 0.0f, 128.0f);
    out.twoSide = a.twoSide;
}

void StateTracker::lightModel(GLenum pname, const float* v)
{
    if (!v) return;
    if (pname == GL_LIGHT_MODEL_AMBIENT) mAttrib.modelAmbient = glm::vec3(v[0], v[1], v[2]);
    if (pname == GL_LIGHT_MODEL_LOCAL_VIEWER) mAttrib.localViewer = v[0] != 0.0f;
    if (pname == GL_LIGHT_MODEL_TWO_SIDE) mAttrib.twoSide = v[0] != 0.0f;
}

size_t StateTracker::keyLight() const
{
    // The brightest enabled light gives the styles their L: the others only brighten.
    const AttribState& a = mAttrib;
    size_t key = 0;
    float best = -1.0f;
    for (size_t i = 0; i < 8; ++i) {
        if (!(a.lightsOn & (1u << i))) continue;
        const float y = glm::dot(a.lightDiffuse[i], glm::vec3(0.299f, 0.587f, 0.114f));
        if (y > best) {
            best = y;
            key = i;
        }
    }
    return key;
}

bool StateTracker::additiveGlow(bool& textured, bool& sourceAlpha) const
{
    const AttribState& a = mAttrib;
    if (!a.blend || a.blendDst != GL_ONE || (a.blendSrc != GL_ONE && a.blendSrc != GL_SRC_ALPHA) ||
        mProgram != 0 || a.vertexProgram || a.fragmentProgram) {
        return false;
    }
    textured = a.texture2D && sceneTexture(mBoundTexture) != 0;
    sourceAlpha = a.blendSrc == GL_SRC_ALPHA;
    return true;
}

StateTracker::ListDraws StateTracker::listDraws(GLuint list) const
{
    struct State {
        bool texture2D;
        GLuint bound; // unit 0's 2D texture
        bool blend;
        GLenum src, dst;
    };
    struct Walk {
        const StateTracker& t;
        ListDraws out;
        State now;
        int unit;
        std::vector<State> saved; // glPushAttrib inside the lists
        size_t work = 0;
        void run(GLuint id, int depth)
        {
            auto it = t.mLists.find(id);
            if (it == t.mLists.end() || depth >= 64) return;
            for (const ListItem& item : it->second.items) {
                if (++work > kListWorkLimit) return;
                if (item.batch >= 0) {
                    const size_t n = it->second.batches[size_t(item.batch)].vertices.size();
                    const bool on = now.texture2D && t.sceneTexture(now.bound) != 0;
                    (on ? out.textured : out.untextured) += n;
                    out.blendsLeft = out.blendsLeft ||
                                     (changesPixels(now.blend, now.src, now.dst) &&
                                      !byAlpha(now.blend, now.src, now.dst));
                    continue;
                }
                step(item.call, depth);
            }
        }
        void step(const std::vector<uint8_t>& call, int depth)
        {
            CallReader r(call.data(), call.size(), t.mBlobs, t.mOpcodes);
            const uint16_t opcode = r.opcode();
            if (opcode == op::glEnable || opcode == op::glDisable) {
                const GLenum cap = r.get<GLenum>();
                const bool on = opcode == op::glEnable;
                if (r.ok() && cap == GL_TEXTURE_2D && unit == 0) now.texture2D = on;
                if (r.ok() && cap == GL_BLEND) now.blend = on;
            } else if (opcode == op::glBindTexture) {
                const GLenum target = r.get<GLenum>();
                const GLuint texture = r.get<GLuint>();
                if (r.ok() && target == GL_TEXTURE_2D && unit == 0) now.bound = texture;
            } else if (opcode == op::glActiveTexture) {
                const GLenum u = r.get<GLenum>();
                if (r.ok()) unit = int(u) - int(GL_TEXTURE0);
            } else if (opcode == op::glBlendFunc || opcode == op::glBlendFuncSeparate) {
                const GLenum src = r.get<GLenum>();
                const GLenum dst = r.get<GLenum>();
                if (r.ok()) {
                    now.src = src;
                    now.dst = dst;
                }
            } else if (opcode == op::glPushAttrib) {
                saved.push_back(now);
            } else if (opcode == op::glPopAttrib && !saved.empty()) {
                now = saved.back();
                saved.pop_back();
            } else if (opcode == op::glCallList) {
                const GLuint inner = r.get<GLuint>();
                if (r.ok()) run(inner, depth + 1);
            }
        }
    };
    const AttribState& a = mAttrib;
    Walk walk{*this, {}, {a.texture2D, mBoundTexture, a.blend, a.blendSrc, a.blendDst},
              mActiveUnit, {}};
    walk.run(list, 0);
    return walk.out;
}

bool StateTracker::blending() const
{
    return changesPixels(mAttrib.blend, mAttrib.blendSrc, mAttrib.blendDst);
}

bool StateTracker::translucent() const
{
    return byAlpha(mAttrib.blend, mAttrib.blendSrc, mAttrib.blendDst);
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

uint32_t StateTracker::currentMaterialId()
{
    const AttribState& a = mAttrib;
    // Unlit or colour-material keys leave the diffuse zero; their first two entries tell
    // them apart from lit ones.
    std::array<float, 7> key = {float(a.lighting), float(a.frontColorMaterial()),
                                float(detailTexture()), 0.0f, 0.0f, 0.0f, 0.0f};
    if (a.lighting && !a.frontColorMaterial()) {
        const glm::vec4& d = a.material.diffuse;
        key[3] = d.r;
        key[4] = d.g;
        key[5] = d.b;
        key[6] = d.a;
    }
    auto it = mMaterialIds.find(key);
    if (it != mMaterialIds.end()) return it->second;
    uint32_t id = uint32_t(mMaterialIds.size()) + 1;
    mMaterialIds.emplace(key, id);
    return id;
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

void StateTracker::batchMaterial(GLenum face, GLenum pname, const float* v)
{
    if (!mInBegin || face == GL_BACK || !v) return;
    if (pname != GL_DIFFUSE && pname != GL_AMBIENT_AND_DIFFUSE && pname != GL_AMBIENT) return;
    TrackedBatch::MaterialChange change;
    change.first = uint32_t(mBatch.vertices.size());
    change.setsDiffuse = pname != GL_AMBIENT;
    change.setsAmbient = pname != GL_DIFFUSE;
    if (change.setsDiffuse) change.diffuse = {v[0], v[1], v[2], v[3]};
    if (change.setsAmbient) change.ambient = {v[0], v[1], v[2]};
    mBatch.materials.push_back(change);
}

void StateTracker::material(GLenum face, GLenum pname, const float* v)
{
    batchMaterial(face, pname, v);
    if (!v) return;
    if (face != GL_BACK) mAttrib.material.set(pname, v);
    // Only GL's two-sided lighting shows it (FixedLighting, for the replica).
    if (face == GL_BACK || face == GL_FRONT_AND_BACK) mAttrib.backMaterial.set(pname, v);
}

void StateTracker::newList(GLuint list, GLenum mode)
{
    if (mCompiling || list == 0) return; // GL_INVALID_OPERATION / GL_INVALID_VALUE
    mCompiling = true;
    mCompileAndExecute = mode == GL_COMPILE_AND_EXECUTE;
    mCompilingList = list;
    mCompiled = List();
    mListSetsColor = mListSetsNormal = mListSetsTexCoord = false;
}

void StateTracker::endList()
{
    if (!mCompiling) return;
    mCompiling = false;
    mLists[mCompilingList] = std::move(mCompiled);
    mCompiled = List();
}

void StateTracker::callList(GLuint list)
{
    if (mCompiling) mCompiled.calls.push_back(list); // executed now: GL_COMPILE_AND_EXECUTE
    // A list held back is held as a whole (the compositor masked the whole glCallList).
    const bool top = mHoldingList == 0 && mPassingList == 0 && mCallDepth == 0;
    const bool hold = mHolding && top && wouldHoldList(list);
    const bool pass = top && !hold;
    mHoldingList += hold;
    mPassingList += pass;
    if (mCallDepth == 0) mListWork = 0;
    callListBody(list);
    mPassingList -= pass;
    mHoldingList -= hold;
}

void StateTracker::callLists(GLsizei n, GLenum type, const void* lists)
{
    const bool top = mHoldingList == 0 && mPassingList == 0 && mCallDepth == 0;
    const bool hold = mHolding && top && wouldHoldLists(n, type, lists);
    if (!hold) otherDraw(); // text, typically
    const bool pass = top && !hold;
    mHoldingList += hold;
    mPassingList += pass;
    if (mCallDepth == 0) mListWork = 0;
    const uint8_t* p = static_cast<const uint8_t*>(lists);
    for (GLsizei i = 0; p && i < n; ++i) {
        const GLuint list = mListBase + listId(type, p, i);
        if (mCompiling) mCompiled.calls.push_back(list); // GL_COMPILE_AND_EXECUTE
        callListBody(list);
    }
    mPassingList -= pass;
    mHoldingList -= hold;
}

bool StateTracker::wouldHoldLists(GLsizei n, GLenum type, const void* lists) const
{
    const uint8_t* p = static_cast<const uint8_t*>(lists);
    if (!p || n <= 0 || n > 4096 || !wouldHold(GL_TRIANGLES)) return false;
    // Lists of state only (a material, a transform) go along with the ones that draw.
    bool anyBatch = false;
    for (GLsizei i = 0; i < n; ++i) {
        const GLuint list = mListBase + listId(type, p, i);
        if (!listHoldable(list, anyBatch) || listDraws(list).blendsLeft) return false;
    }
    return anyBatch;
}

void StateTracker::callListBody(GLuint list)
{
    auto it = mLists.find(list);
    // GL_MAX_LIST_NESTING is 64: a list that calls itself stops there, as in the driver.
    if (it == mLists.end() || mCallDepth >= 64) return;
    const List& body = it->second;
    mListWork += body.items.size() + 1;
    if (mListWork > kListWorkLimit) {
        if (!mListWorkSaid) {
            NPRGL_WARN("a display list runs more than %llu list items in one call (lists calling "
                       "themselves over and over): nprgl stops following it there, so what the "
                       "rest would draw is not styled",
                       static_cast<unsigned long long>(kListWorkLimit));
            mListWorkSaid = true;
        }
        return;
    }
    ++mCallDepth;
    ++mListDepth;
    const bool callerNormal = currentNormalCounts(); // before the list's draws clear it
    for (const ListItem& item : body.items) {
        if (item.batch >= 0) {
            const TrackedBatch& compiled = body.batches[size_t(item.batch)];
            TrackedBatch batch;
            batch.vertices = takeVertices();
            batch.vertices.assign(compiled.vertices.begin(), compiled.vertices.end());
            batch.mode = compiled.mode;
            // The driver draws a list's quads as indexed ones (reconstruct::QuadCut).
            batch.quadCut = reconstruct::QuadCut::V1V3;
            batch.hasNormals = compiled.hasNormals;
            batch.materials = compiled.materials;
            batch.beginMaterial = compiled.beginMaterial;
            batch.beginAmbient = compiled.beginAmbient;
            const List::Inherits& from = body.inherits[size_t(item.batch)];
            if (from.normal) batch.hasNormals = batch.hasNormals || callerNormal;
            // What the list did not set itself comes from the state at this call.
            if (from.color || from.normal || from.texcoord ||
                batch.hasNormals != compiled.hasNormals) {
                for (TrackedVertex& v : batch.vertices) {
                    if (from.color) v.color = mCurrent.color;
                    if (from.normal) v.normal = mCurrent.normal;
                    if (from.texcoord) v.texcoord = mCurrent.texcoord;
                    v.hasNormal = batch.hasNormals;
                }
            }
            emit(std::move(batch));
        } else {
            std::string ignored;
            runCalls(item.call.data(), item.call.size(), false, ignored);
        }
    }
    --mListDepth;
    --mCallDepth;
}

void StateTracker::deleteLists(GLuint list, GLsizei range)
{
    for (GLsizei i = 0; i < range; ++i) mLists.erase(list + GLuint(i));
}

void StateTracker::activeTexture(GLenum unit)
{
    if (unit >= GL_TEXTURE0 && unit < GL_TEXTURE0 + 32) mActiveUnit = int(unit - GL_TEXTURE0);
    mMatrices.setUnit(mActiveUnit);
}

void StateTracker::bindTexture(GLenum target, GLuint texture)
{
    if (target == GL_TEXTURE_CUBE_MAP && size_t(mActiveUnit) < mUnitCubeTextures.size()) {
        mUnitCubeTextures[size_t(mActiveUnit)] = texture;
    }
    if (target == GL_TEXTURE_2D && mActiveUnit == 0) mBoundTexture = texture;
    if (target == GL_TEXTURE_2D && size_t(mActiveUnit) < mUnitTextures.size()) {
        mUnitTextures[size_t(mActiveUnit)] = texture;
    }
}

bool StateTracker::opaqueAlpha(const TrackedBatch& batch) const
{
    const AttribState& a = mAttrib;
    const int u = surfaceUnit();
    const GLenum mode = u >= 0 ? a.envMode[size_t(u)] : GL_MODULATE;
    // The texture's alpha counts unless GL_DECAL (the fragment keeps the colour's alpha).
    if (batch.texture != 0 && mode != GL_DECAL &&
        !mTextures.opaque(styles::textureName(batch.texture))) {
        return false;
    }
    if (mode == GL_REPLACE && batch.texture != 0) return true;
    // Within half a step of 8 bits of 1 blends no pixel differently (programs' computed
    // alphas are 0.99999994 as often as 1).
    constexpr float kOpaque = 1.0f - 0.5f / 255.0f;
    for (const TrackedVertex& v : batch.vertices) {
        if (!(v.color.a >= kOpaque)) return false;
    }
    return true;
}

void StateTracker::addEvenSpecular(TrackedBatch& batch) const
{
    // GL's specular term at each vertex (Blinn's half-vector, an infinite viewer), per light;
    // the least of it over the batch lights all of the batch. A flat face under a light near
    // its mirror angle (sproingies' stairs: a dark material made pale by its shine) is that
    // bright all over; on a curved surface the least is about nothing, and its highlight is
    // the styles' highlight band.
    const AttribState& a = mAttrib;
    if (!(glm::dot(a.material.specular, a.material.specular) > 0.0f)) return;
    struct Shine {
        glm::vec3 colour;
        size_t light;
        float lowest = INFINITY;
    };
    std::array<Shine, 8> shines;
    size_t count = 0;
    for (size_t i = 0; i < 8; ++i) {
        const glm::vec3 colour = glm::max(a.lightSpecular[i], 0.0f) * a.material.specular;
        if ((a.lightsOn & (1u << i)) && glm::dot(colour, colour) > 0.0f) {
            shines[count++] = {colour, i};
        }
    }
    constexpr float kNone = 1e-3f;
    const glm::mat4& modelview = batch.modelview;
    const glm::mat3 normals = glm::inverseTranspose(glm::mat3(modelview));
    size_t shining = count; // lights every vertex so far has some of
    for (const TrackedVertex& v : batch.vertices) {
        if (shining == 0) return; // a vertex without any: nothing even
        const glm::vec3 eye = glm::vec3(modelview * glm::vec4(v.position, 1.0f));
        const glm::vec3 n = glm::normalize(normals * v.normal);
        for (size_t k = 0; k < count; ++k) {
            Shine& shine = shines[k];
            if (!(shine.lowest > kNone)) continue;
            const size_t i = shine.light;
            glm::vec3 l;
            float reach = 0.0f;
            float s = 0.0f;
            if (FixedLighting::towardsLight(a, i, eye, l, reach)) {
                const float nh = glm::dot(n, glm::normalize(l + glm::vec3(0.0f, 0.0f, 1.0f)));
                if (glm::dot(n, l) > 0.0f && nh > 0.0f) {
                    s = std::pow(nh, a.material.shininess) * reach;
                }
            }
            shine.lowest = std::min(shine.lowest, std::isfinite(s) ? s : 0.0f);
            if (!(shine.lowest > kNone)) --shining;
        }
    }
    glm::vec3 even(0.0f);
    for (size_t k = 0; k < count; ++k) {
        const float lowest = shines[k].lowest;
        if (lowest > kNone && std::isfinite(lowest)) {
            even += shines[k].colour * std::min(lowest, 1.0f);
        }
    }
    if (even == glm::vec3(0.0f)) return;
    for (TrackedVertex& v : batch.vertices) {
        v.color = glm::min(v.color + glm::vec4(even, 0.0f), glm::vec4(1.0f));
    }
}

void StateTracker::replacedByTexture(TrackedBatch& batch) const
{
    const int u = surfaceUnit();
    if (batch.texture == 0 || u < 0) return;
    const GLenum mode = mAttrib.envMode[size_t(u)];
    const GLuint name = styles::textureName(batch.texture);
    const bool opaque = mTextures.opaque(name);
    // GL_REPLACE takes the texture's alpha too where it has one (kept opaque: opaqueAlpha);
    // an alpha-only texture replaces the alpha alone. GL_DECAL keeps the fragment's alpha and
    // mixes the colours by the texture's, so only an opaque texture replaces them.
    if ((mode == GL_REPLACE && !mTextures.alphaOnly(name)) || (mode == GL_DECAL && opaque)) {
        for (TrackedVertex& v : batch.vertices) v.color = glm::vec4(glm::vec3(1.0f), v.color.a);
    }
}

void StateTracker::texEnv(GLenum target, GLenum pname, GLenum mode)
{
    if (target != GL_TEXTURE_ENV || mActiveUnit >= 8) return;
    const size_t u = size_t(mActiveUnit);
    AttribState& a = mAttrib;
    // Another value is refused by the driver (GL_INVALID_ENUM), which keeps the one it had.
    switch (pname) {
    case GL_TEXTURE_ENV_MODE:
        if (mode == GL_MODULATE || mode == GL_REPLACE || mode == GL_DECAL || mode == GL_BLEND ||
            mode == GL_ADD || mode == GL_COMBINE) {
            a.envMode[u] = mode;
        }
        break;
    case GL_COMBINE_RGB:
        if (mode == GL_REPLACE || mode == GL_MODULATE || mode == GL_ADD ||
            mode == GL_ADD_SIGNED || mode == GL_INTERPOLATE || mode == GL_SUBTRACT ||
            mode == GL_DOT3_RGB || mode == GL_DOT3_RGBA) {
            a.combineRgb[u] = mode;
        }
        break;
    case GL_RGB_SCALE:
        if (mode == 1 || mode == 2 || mode == 4) a.rgbScale[u] = float(mode);
        break;
    case GL_SOURCE0_RGB:
    case GL_SOURCE1_RGB:
        a.combineArgs[4 * u + (pname - GL_SOURCE0_RGB)] = mode;
        break;
    case GL_OPERAND0_RGB:
    case GL_OPERAND1_RGB:
        a.combineArgs[4 * u + 2 + (pname - GL_OPERAND0_RGB)] = mode;
        break;
    default:
        break;
    }
}

bool StateTracker::layerEffect(int unit, glm::vec3& scale, glm::vec3& offset) const
{
    const AttribState& a = mAttrib;
    const size_t u = size_t(unit);
    // The unit's texture: a cube map where one is enabled (GL takes it over a 2D one).
    glm::vec3 m;
    if (a.cubeUnits & (1u << u)) {
        if (!mTextures.cubeMean(mUnitCubeTextures[u], m)) return false;
    } else {
        const glm::vec3* mean = mTextures.mean(mUnitTextures[u]);
        if (!mean) return false;
        m = *mean;
    }
    GLenum function = a.envMode[u];
    float k = 1.0f;
    if (function == GL_COMBINE) {
        // The texture with the colour so far, either way round, each as its colour.
        const GLenum* args = &a.combineArgs[4 * u];
        const bool plain = ((args[0] == GL_TEXTURE && args[1] == GL_PREVIOUS) ||
                            (args[0] == GL_PREVIOUS && args[1] == GL_TEXTURE)) &&
                           args[2] == GL_SRC_COLOR && args[3] == GL_SRC_COLOR;
        if (!plain) return false;
        function = a.combineRgb[u];
        k = a.rgbScale[u];
    }
    // As an affine map of the colour so far: c' = scale c + offset, with the texel's mean.
    switch (function) {
    case GL_MODULATE: scale = k * m; offset = glm::vec3(0.0f); return true;
    case GL_ADD: scale = glm::vec3(k); offset = k * m; return true;
    case GL_ADD_SIGNED: scale = glm::vec3(k); offset = k * (m - 0.5f); return true;
    default: return false; // replacing, interpolating, subtracting, dot products: not followed
    }
}

void StateTracker::layerEffects(TrackedBatch& batch) const
{
    uint32_t layers = droppedLayers();
    // A surface textured by a cube map alone (an environment on reflection coordinates, the
    // styles draw none) is dropped as a layer is: its mean tint stays.
    const int surface = surfaceUnit();
    if (surface >= 0 && batch.texture == 0 && batch.generated.texture == 0 &&
        (mAttrib.cubeUnits & (1u << surface))) {
        layers |= 1u << surface;
    }
    for (int u = 0; u < 8; ++u) {
        glm::vec3 scale, offset;
        if (!(layers & (1u << u)) || !layerEffect(u, scale, offset)) continue;
        // GL applies the units in order: this one to what the ones before it made.
        batch.layerScale *= scale;
        batch.layerOffset = scale * batch.layerOffset + offset;
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

void StateTracker::texSubImage2D(GLenum target, GLint level, GLsizei width, GLsizei height,
                                 GLenum format, GLenum type, const void* pixels)
{
    if (target != GL_TEXTURE_2D || level != 0 || size_t(mActiveUnit) >= mUnitTextures.size()) {
        return;
    }
    mTextures.subImage2D(mUnitTextures[size_t(mActiveUnit)], width, height, format, type,
                         pixels, mImageBytes);
}

uint64_t StateTracker::textureHash(GLuint texture) const
{
    return mTextures.hash(texture);
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
