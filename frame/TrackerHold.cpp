// What is held for the styles and what is left as the program draws it, and why.
#include "frame/StateTracker.h"

#include "frame/TrackerGl.h"

#include <xxhash.h>

#include <cstring>

namespace nprgl {

using namespace tracker;

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

bool StateTracker::blending() const
{
    return changesPixels(mAttrib.blend, mAttrib.blendSrc, mAttrib.blendDst);
}

bool StateTracker::translucent() const
{
    return byAlpha(mAttrib.blend, mAttrib.blendSrc, mAttrib.blendDst);
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

} // namespace nprgl
