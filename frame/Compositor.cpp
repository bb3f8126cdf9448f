#include "frame/Compositor.h"

#include "common/Log.h"
#include "frame/BatchReplay.h"
#include "frame/Recorder.h"
#include "shim/Context.h"
#include "shim/OwnGlCalls.h"
#include "shim/RealGl.h"
#include "shim/RecordingDispatch.h"
#include "shim/ThreadState.h"
#include "styles/textures/AbstractTextures.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <chrono>
#include <cstring>

namespace nprgl {

namespace {

void* realProc(const char* name) { return realProcAddress(name); }

glm::vec3 lightDirection(const TrackedBatch& b)
{
    if (b.lights.count > 0) {
        const glm::vec4 key = b.lights.lights[0].position; // the brightest
        glm::vec3 toLight = glm::vec3(key);
        if (key.w != 0.0f) {
            // A positional light: towards it from the object's origin.
            toLight = glm::vec3(key) / key.w - glm::vec3(b.modelview[3]);
        }
        if (glm::dot(toLight, toLight) > 1e-12f) return glm::normalize(toLight);
    }
    return glm::normalize(glm::vec3(-0.4f, 0.5f, 1.0f)); // a head-light from the upper left
}

} // namespace

Compositor::Compositor(Context& ctx, Recorder& recorder)
    : mContext(ctx), mRecorder(recorder), mSettings(ctx.config().style)
{
    mHasStyles = mSettings.chain().front()->create != nullptr;
    // The textures' content as the state model knows it: the styles' abstractions are
    // cached by it (texture 0's image goes by the scene's name for it).
    mChain.context().textureContent = [this](GLuint texture) {
        return mTracker.textureHash(texture == styles::kDefaultTexture ? 0 : texture);
    };
}

void Compositor::finishStyleWorkAtOnce() { styles::AbstractTextures::setWait(true); }

Compositor::~Compositor() { reportRunCounts(); }

void Compositor::reportRunCounts() { report(mRunCounts, mChain.textureCounts(), ""); }

void Compositor::reportRunCountsAtFrameEnd()
{
    std::lock_guard lock(mFrameEndCountsMutex);
    report(mFrameEndCounts, mFrameEndTextures,
           " (to its last frame end: it is current on another thread)");
}

void Compositor::report(const DrawCounts& counts, const styles::AbstractTextures::Counts& textures,
                        const char* note)
{
    if (counts.styled() == 0 && counts.left() == 0) return;
    if (mRunCountsReported.exchange(true)) return;
    NPRGL_INFO("context %u: 3D polygon draws: %s%s", mContext.serial(), counts.describe().c_str(),
               note);
    if (textures.any()) {
        NPRGL_INFO("context %u: textures as drawings: %s%s", mContext.serial(),
                   textures.describe().c_str(), note);
    }
}

void Compositor::syncStream()
{
    if (mBroken) return;
    CallWriter& w = mRecorder.writer();
    if (mSynced >= w.size()) return;
    std::string error;
    const bool ok = mTracker.feed(w.data() + mSynced, w.size() - mSynced, &mBlobs, error);
    mBlobs.kept.clear();
    if (!ok) {
        NPRGL_ERROR("context %u: cannot follow the program's GL calls (%s); styles off, the "
                    "program draws as without nprgl from here",
                    mContext.serial(), error.c_str());
        mBroken = true;
        mTracker.setHolding(false);
    }
    mSynced = w.size();
    // Translucent passes the tracker merged into their held objects.
    const uint64_t merged = mTracker.mergedPasses();
    if (merged == mMergedSeen) return;
    noteMerged(merged - mMergedSeen);
    mMergedSeen = merged;
}

void Compositor::keepBlob(uint64_t hash, const void* data, size_t size)
{
    if (mBroken) return;
    const uint8_t* p = static_cast<const uint8_t*>(data);
    mBlobs.kept.try_emplace(hash, p, p + size);
}

const std::vector<uint8_t>* Compositor::Blobs::blob(uint64_t hash, std::string& error)
{
    auto it = kept.find(hash);
    if (it != kept.end()) return &it->second;
    error = "blob not kept";
    return nullptr;
}

bool Compositor::ready()
{
    if (mPhase == Phase::Ready) return !mBroken && mEnabled && mHasStyles;
    if (mPhase == Phase::Off || mBroken || mInFlush) return false;
    checkContext();
    if (mPhase == Phase::Off) return false;
    // Our set-up (texture uploads) would be compiled into the program's list: wait.
    GLint list = 0;
    gRealGl.glGetIntegerv(GL_LIST_INDEX, &list);
    if (list != 0) return false;
    if (!startStyles()) {
        mPhase = Phase::Off;
        return false;
    }
    GLint viewport[4] = {}, scissor[4] = {}, maxAttrib = 16, maxClient = 16;
    gRealGl.glGetIntegerv(GL_VIEWPORT, viewport);
    gRealGl.glGetIntegerv(GL_SCISSOR_BOX, scissor);
    const bool scissorTest = gRealGl.glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE;
    gRealGl.glGetIntegerv(GL_MAX_ATTRIB_STACK_DEPTH, &maxAttrib);
    gRealGl.glGetIntegerv(GL_MAX_CLIENT_ATTRIB_STACK_DEPTH, &maxClient);
    syncStream();
    mTracker.setViewport({viewport[0], viewport[1], viewport[2], viewport[3]});
    mTracker.setScissor({scissor[0], scissor[1], scissor[2], scissor[3]});
    mTracker.setScissorTest(scissorTest);
    GLfloat depthRange[2] = {0.0f, 1.0f};
    gRealGl.glGetFloatv(GL_DEPTH_RANGE, depthRange);
    mTracker.setDepthRange(depthRange[0], depthRange[1]);
    mTracker.setStackLimits(maxAttrib, maxClient);
    // Off or without styles, the tracker must not take the program's draws for held ones.
    mTracker.setHolding(mEnabled && mHasStyles);
    // While a held glBegin..glEnd is open: the context's table with vertices recorded only.
    mHeldNext = mNext;
    installHeldRecording(mHeldNext);
    mHeldTable = mContext.dispatch();
    installHeldRecording(mHeldTable);
    installEnd(mHeldTable);
    mPhase = Phase::Ready;
    return !mBroken && mEnabled && mHasStyles;
}

void Compositor::checkContext()
{
    if (mPhase != Phase::Unknown) return;
    const ContextCaps& caps = mContext.caps();
    if (!caps.es && !caps.core && caps.atLeast(3, 0)) return;
    const std::string& version = mContext.version();
    NPRGL_WARN("context %u: %s%s; styles need OpenGL 3.0 compatibility or newer: "
               "passthrough",
               mContext.serial(), version.empty() ? "no GL version" : version.c_str(),
               caps.core ? " (core profile)" : "");
    mPhase = Phase::Off;
    mContext.stopStyling();
}

void Compositor::keepProgramError(GLenum error) { mContext.keepProgramError(error); }

bool Compositor::startStyles()
{
    mBindFramebuffer = reinterpret_cast<PFNGLBINDFRAMEBUFFERPROC>(realProc("glBindFramebuffer"));
    if (!mSaved.resolve()) {
        NPRGL_WARN("context %u: the driver lacks framebuffer objects; passthrough",
                   mContext.serial());
        return false;
    }
    std::string error;
    if (!startChain(false, error)) {
        NPRGL_WARN("context %u: %s; passthrough", mContext.serial(), error.c_str());
        return false;
    }
    NPRGL_INFO("context %u: style %s on %s", mContext.serial(), mSettings.chainName().c_str(),
               mContext.renderer().c_str());
    return true;
}

bool Compositor::startChain(bool restart, std::string& error)
{
    OwnGlCalls own;
    if (!mSaved.save()) {
        error = "the program's state could not be saved";
        return false;
    }
    if (restart) mChain.shutdown();
    const bool ok = !mHasStyles || mChain.init(mSettings, &realProc, error);
    mSaved.restore();
    own.finish();
    mShading = ok && mHasStyles && mChain.hasShading();
    mTintLeft = false;
    bool programLighting = false;
    for (const StyleInfo* info : mSettings.chain()) {
        mTintLeft = mTintLeft || info->name == "coverage";
        programLighting = programLighting || info->programLighting;
    }
    mTracker.setProgramLighting(mShading && programLighting);
    return ok;
}

void Compositor::restyle(const StyleSettings& settings, bool announce)
{
    flush();
    mSettings = settings;
    mHasStyles = mSettings.chain().front()->create != nullptr;
    // Not started yet: it starts with the new settings; off (core profile, no FBOs): stays.
    if (mPhase != Phase::Ready || mBroken) return;
    mTracker.setHolding(false); // nothing is held while the chain restarts
    std::string error;
    if (!startChain(true, error)) {
        NPRGL_WARN("context %u: style %s cannot start: %s; passthrough until the next change",
                   mContext.serial(), mSettings.chainName().c_str(), error.c_str());
        mHasStyles = false;
        mTracker.setHolding(false);
        return;
    }
    mTracker.setHolding(mEnabled && mHasStyles);
    if (!announce) return;
    NPRGL_INFO("context %u: configuration changed: style now %s", mContext.serial(),
               mSettings.chainName().c_str());
}

PickResult Compositor::pick(int x, int y, int windowHeight, uint64_t& textureHash) const
{
    const PickResult hit = pickScene(mScene, float(x) + 0.5f, float(windowHeight - 1 - y) + 0.5f);
    textureHash = hit.texture ? mTracker.textureHash(styles::textureName(hit.texture)) : 0;
    return hit;
}

void Compositor::endFrameCounts()
{
    mLastFrameCounts = mFrameCounts;
    mFrameCounts.clear();
    {
        std::lock_guard lock(mFrameEndCountsMutex); // taken only here and at exit
        mFrameEndCounts = mRunCounts;
        mFrameEndTextures = mChain.textureCounts();
    }
    mLastFrameComposeMs = std::exchange(mFrameComposeMs, 0.0);
}

void Compositor::setEnabled(bool enabled)
{
    if (enabled == mEnabled) return;
    flush();
    mEnabled = enabled;
    if (mPhase == Phase::Ready) mTracker.setHolding(mEnabled && mHasStyles);
    NPRGL_INFO("context %u: styling %s", mContext.serial(), enabled ? "on" : "off");
}

void Compositor::tintBegin(GLuint list)
{
    overlayBegin();
    mFresh.drawn = true;
    if (!mLeftNow) return;
    mLeftNow = false;
    bool textured = false, sourceAlpha = false;
    if (!mTintLeft && mEnabled && mHasStyles && mChain.inksGlows() &&
        mTracker.additiveGlow(textured, sourceAlpha)) {
        if (list) {
            // The ink's texturing is set once for the call, and a list may switch it
            // (gibson's towers: untextured faces, then textured glyphs, in lists of their own).
            const StateTracker::ListDraws drawn = mTracker.listDraws(list);
            if (drawn.textured + drawn.untextured > 0) textured = drawn.textured > 0;
            if (drawn.textured > 0 && drawn.untextured > 0) {
                textured = drawn.textured >= drawn.untextured;
                if (!mMixedGlowSaid) {
                    NPRGL_INFO("context %u: a glowing display list draws both with and without "
                               "its texture; its ink takes the texture of most of its vertices "
                               "(%s)",
                               mContext.serial(), textured ? "textured" : "untextured");
                    mMixedGlowSaid = true;
                }
            }
        }
        // On the chain's page a glow is drawn as ink of its colour (GlowInk); the attribute
        // stack gives the program's blending back, glowEnd its program binding (none).
        gRealGl.glPushAttrib(GL_COLOR_BUFFER_BIT);
        mChain.glowBegin(textured, sourceAlpha, mTracker.fogMode());
        mGlowing = true;
        if (!mGlowSaid) {
            NPRGL_INFO("context %u: additive glows are drawn as ink of their colour on the page",
                       mContext.serial());
            mGlowSaid = true;
        }
        return;
    }
    if (!mTintLeft) return;
    if (mTracker.ownShaders()) {
        // A program's own shaders ignore the fixed pipeline's fog: blending keeps their red
        // alone (dark red where they draw little red), over nothing behind.
        gRealGl.glPushAttrib(GL_ENABLE_BIT | GL_COLOR_BUFFER_BIT);
        gRealGl.glEnable(GL_BLEND);
        gRealGl.glBlendColor(1.0f, 0.0f, 0.0f, 1.0f);
        gRealGl.glBlendEquation(GL_FUNC_ADD);
        gRealGl.glBlendFuncSeparate(GL_CONSTANT_COLOR, GL_ZERO, GL_ONE, GL_ZERO);
        mTinting = true;
        return;
    }
    // Fog at an overwhelming density turns every fragment of the fixed-function pipeline into
    // the fog colour, whatever its colours, lighting and textures; the attribute stack gives
    // the program's fog back.
    // Blended, it is laid over what is behind by its alpha: added, the red of a glow over a
    // light tint read white or pink, and the draw was not seen as left.
    gRealGl.glPushAttrib(GL_FOG_BIT | GL_ENABLE_BIT | GL_COLOR_BUFFER_BIT);
    const float red[4] = {1.0f, 0.0f, 0.0f, 1.0f};
    gRealGl.glEnable(GL_FOG);
    gRealGl.glFogi(GL_FOG_MODE, GL_EXP);
    gRealGl.glFogf(GL_FOG_DENSITY, 1.0e6f);
    gRealGl.glFogfv(GL_FOG_COLOR, red);
    gRealGl.glBlendEquation(GL_FUNC_ADD);
    gRealGl.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    mTinting = true;
}

void Compositor::tintEnd()
{
    if (mGlowing) {
        mChain.glowEnd();
        gRealGl.glPopAttrib();
        mGlowing = false;
    }
    if (mTinting) {
        gRealGl.glPopAttrib();
        mTinting = false;
    }
    overlayEnd();
}

void Compositor::noteUnstyled(bool polygonal)
{
    if (polygonal) noteLeft(mTracker.unstylableState());
}

void Compositor::noteLeft(const char* why)
{
    // Say once per reason why 3D polygons are left as the program draws them: the picture
    // is then partly the program's own, and the user should know why.
    // Compiled only (GL_COMPILE), nothing is drawn now: the list's calls count.
    if (!why || !mTracker.is3D() || !mTracker.executing()) return;
    // The coverage style paints it red, unless the attribute stack has no room to do so. Not
    // while a list compiles: the tint's own commands would be compiled into it. Nor into a
    // framebuffer read back: its colours are the program's data.
    mLeftNow = std::strcmp(why, "a full attribute stack") != 0 &&
               std::strcmp(why, StateTracker::kDrawingDataWhy) != 0 && !mTracker.compiling();
    mFrameCounts.noteLeft(why);
    if (!mRunCounts.noteLeft(why)) return;
    NPRGL_INFO("context %u: 3D polygons drawn with %s are left as the program draws them",
               mContext.serial(), why);
}

Compositor::Placement Compositor::placeDraw(GLenum mode, bool layers)
{
    const bool isReady = ready();
    overlayPlaced();
    if (!isReady) return Placement::Left;
    syncStream();
    if (!mTracker.wouldHold(mode)) {
        // Decided once the tracker has its vertices (settleLayer), before it reaches the
        // driver.
        if (layers && mHeld && mTracker.mayLayer(mode)) {
            mLayerWhy = mTracker.unstylableState();
            mTracker.watchRepeats();
            return Placement::Layer;
        }
        noteUnstyled(mode >= GL_TRIANGLES && mode <= GL_POLYGON);
        if (mHeld) flush();
        return Placement::Left;
    }
    noteLayers();
    noteHeld();
    return Placement::Held;
}

size_t Compositor::streamSize() const { return mRecorder.writer().size(); }

Compositor::Settled Compositor::settleLayer(size_t mark)
{
    // The recorder could not follow the draw's arrays: the driver drew it as it is.
    if (streamSize() == mark) {
        mTracker.repeatedAll(); // ends the watch
        noteLeft(mLayerWhy);
        mLeftNow = false;
        return Settled::Drawn;
    }
    syncStream();
    if (mTracker.repeatedAll()) {
        mRunCounts.noteStyled();
        mFrameCounts.noteStyled();
        noteMerged(1);
        // Without a shading style the program draws its objects itself, layers and all, and
        // the outline styles draw over the whole (a pencil's page covers the shine too).
        return mShading ? Settled::Merged : Settled::Draw;
    }
    noteLeft(mLayerWhy);
    flush(); // what it draws goes over the finished scene
    return Settled::Draw;
}

void Compositor::noteMerged(uint64_t passes)
{
    mRunCounts.noteMerged(passes);
    mFrameCounts.noteMerged(passes);
    if (mMergeSaid) return;
    mMergeSaid = true;
    NPRGL_INFO("context %u: blended passes over geometry it styles (multi-pass surfaces: "
               "detail, light, shine or fog layers) are merged into their object, not drawn "
               "again",
               mContext.serial());
}

void Compositor::noteLayers()
{
    // A lightmap giving the light, and layers not drawn: each said once.
    const int light = mTracker.lightmapUnit();
    if (light >= 0 && !(mLightmapsSaid & (1u << light))) {
        mLightmapsSaid |= 1u << light;
        NPRGL_INFO("context %u: lightmaps on unit %d give the shading styles their light",
                   mContext.serial(), light);
    }
    const uint32_t layers = mTracker.droppedLayers();
    if (!layers || (mLayersSaid & layers) == layers) return;
    mLayersSaid |= layers;
    std::string units;
    for (int u = 0; u < 8; ++u) {
        if (layers & (1u << u)) units += (units.empty() ? "" : "+") + std::to_string(u);
    }
    NPRGL_INFO("context %u: multitextured 3D polygons are styled with their surface's texture; "
               "the layers over it on unit(s) %s (lightmaps, shadows, environment maps) are not "
               "drawn",
               mContext.serial(), units.c_str());
}

// A display list also sets state (materials, shade model...), so one held, or merged as a
// pass, still runs in the driver, writing neither colour nor depth.
void Compositor::callList(GLuint list)
{
    const Placement placed = placeList(list);
    if (placed == Placement::Layer) {
        const size_t mark = streamSize();
        mHeldNext.glCallList(list);
        const Settled settled = settleLayer(mark);
        if (settled == Settled::Merged) {
            mask();
            gRealGl.glCallList(list);
            unmask();
        } else if (settled == Settled::Draw) {
            tintBegin(list);
            gRealGl.glCallList(list); // recorded already
            tintEnd();
        }
        return;
    }
    const bool masked = placed == Placement::Held && mShading;
    if (masked)
        mask();
    else
        tintBegin(list);
    mNext.glCallList(list);
    if (masked)
        unmask();
    else
        tintEnd();
}

Compositor::Placement Compositor::placeList(GLuint list)
{
    const bool isReady = ready();
    overlayPlaced();
    if (!isReady) return Placement::Left;
    syncStream();
    if (!mTracker.wouldHoldList(list)) {
        if (mHeld && mTracker.mayLayerList(list)) {
            mLayerWhy = mTracker.listUnstylable(list);
            mTracker.watchRepeats();
            return Placement::Layer;
        }
        noteLeft(mTracker.listUnstylable(list));
        if (mHeld) flush();
        return Placement::Left;
    }
    noteHeld();
    return Placement::Held;
}

bool Compositor::holdLists(GLsizei n, GLenum type, const void* lists)
{
    const bool isReady = ready();
    overlayPlaced();
    if (!isReady) return false;
    syncStream();
    if (!mTracker.wouldHoldLists(n, type, lists)) {
        noteLeft(mTracker.listsUnstylable(n, type, lists));
        if (mHeld) flush(); // a barrier: what it draws goes over the finished scene
        return false;
    }
    noteHeld();
    return true;
}

void Compositor::noteHeld()
{
    mRunCounts.noteStyled();
    mFrameCounts.noteStyled();
    GLint framebuffer = 0;
    gRealGl.glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    // One scene per framebuffer and per scissor rectangle (the styles draw it confined so).
    const bool scissorTest = mTracker.scissorTest();
    const glm::ivec4 scissor = scissorTest ? mTracker.scissor() : glm::ivec4(0);
    // And per depth range (a first-person weapon drawn in a range of its own).
    const glm::vec2 depthRange = mTracker.depthRange();
    // And per alpha mask of the drawn colours (a depth-only pass joins its colour pass).
    const bool coloured = !mTracker.colourMaskNone();
    const bool alphaWrites = mTracker.colourMaskAlpha();
    if (mHeld && (framebuffer != mHeldFramebuffer || scissorTest != mHeldScissorTest ||
                  scissor != mHeldScissor || depthRange != mHeldDepthRange ||
                  (coloured && mHeldColoured && alphaWrites != mHeldAlphaWrites))) {
        flush();
    }
    if (coloured && !(mHeld && mHeldColoured)) {
        mHeldColoured = true;
        mHeldAlphaWrites = alphaWrites;
    }
    mHeldDepthRange = depthRange;
    mHeldFramebuffer = framebuffer;
    mHeldScissorTest = scissorTest;
    mHeldScissor = scissor;
    mHeld = true;
}

void Compositor::mask()
{
    // Primitives stop before rasterisation (GL 3.0): the list's state changes still happen,
    // and no fragment is shaded for a picture the style draws anyway.
    mSavedDiscard = gRealGl.glIsEnabled(GL_RASTERIZER_DISCARD);
    if (!mSavedDiscard) gRealGl.glEnable(GL_RASTERIZER_DISCARD);
}

void Compositor::unmask()
{
    if (!mSavedDiscard) gRealGl.glDisable(GL_RASTERIZER_DISCARD);
}

void Compositor::begin(GLenum mode)
{
    const Placement placed = placeDraw(mode, true);
    if (placed == Placement::Layer) {
        // Recorded only until glEnd decides whether it is a pass over held geometry.
        mLayerMark = streamSize();
        mHoldingBegin = true;
        mHeldNext.glBegin(mode);
        tThread.dispatch = &mHeldTable;
        return;
    }
    if (placed == Placement::Held && mShading) {
        // Vertices go to the Stream only until glEnd (attribute calls still reach the driver).
        mHoldingBegin = true;
        mHeldNext.glBegin(mode);
        tThread.dispatch = &mHeldTable;
        return;
    }
    tintBegin();
    mNext.glBegin(mode);
}

void Compositor::end()
{
    if (!mHoldingBegin) {
        mNext.glEnd();
        tintEnd();
        return;
    }
    if (mLayerMark == kNoLayer) {
        mHeldNext.glEnd();
        mHoldingBegin = false;
        tThread.dispatch = &mContext.dispatch();
        return;
    }
    // A possible pass: its calls are kept before glEnd, which may turn them into a blob
    // reference when recording to a file.
    const CallWriter& w = mRecorder.writer();
    mLayerCalls.assign(w.data() + mLayerMark, w.data() + w.size());
    const size_t mark = std::exchange(mLayerMark, kNoLayer);
    mHeldNext.glEnd();
    mHoldingBegin = false;
    tThread.dispatch = &mContext.dispatch();
    if (settleLayer(mark) != Settled::Draw) return;
    tintBegin();
    if (!replayBatch(mLayerCalls.data(), mLayerCalls.size()) && !mReplaySaid) {
        mReplaySaid = true;
        NPRGL_ERROR("context %u: a glBegin/glEnd pass could not be given to the driver whole; "
                    "part of it is missing from the picture",
                    mContext.serial());
    }
    gRealGl.glEnd();
    tintEnd();
}

void Compositor::readPixels()
{
    GLint framebuffer = 0;
    if (ready()) gRealGl.glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &framebuffer);
    // A framebuffer object the program reads back holds data (colour-coded picking, results
    // computed by drawing), not picture: from now on what it draws there is its own, and
    // what is held for it now is drawn unstyled before it reads.
    if (framebuffer != 0 && !readBack(framebuffer)) {
        mReadBack.push_back(framebuffer);
        NPRGL_INFO("context %u: the program reads framebuffer %d back (picking, or results "
                   "computed by drawing): what it draws there is left as it draws it",
                   mContext.serial(), framebuffer);
        mPlainFlush = mHeld && mHeldFramebuffer == framebuffer;
    }
    barrier();
    mPlainFlush = false;
    framebufferBound();
}

void Compositor::copyToTexture()
{
    if (ready()) {
        GLint framebuffer = 0;
        gRealGl.glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &framebuffer);
        const uint64_t frame = mContext.frame();
        std::erase_if(mCopied, [&](const Copied& c) { return c.frame + kCopyMemory < frame; });
        const Copied copied{framebuffer, mTracker.viewport(), frame};
        auto same = [&](const Copied& c) {
            return c.framebuffer == copied.framebuffer && c.viewport == copied.viewport;
        };
        auto it = std::find_if(mCopied.begin(), mCopied.end(), same);
        if (it != mCopied.end())
            it->frame = frame;
        else if (mCopied.size() < 64)
            mCopied.push_back(copied);
    }
    mCopyFlush = true;
    barrier();
    mCopyFlush = false;
}

bool Compositor::copiedRecently(GLint framebuffer, const glm::ivec4& viewport) const
{
    const uint64_t frame = mContext.frame();
    return std::any_of(mCopied.begin(), mCopied.end(), [&](const Copied& c) {
        return c.framebuffer == framebuffer && c.viewport == viewport &&
               c.frame + kCopyMemory >= frame;
    });
}

bool Compositor::readBack(GLint framebuffer) const
{
    return std::find(mReadBack.begin(), mReadBack.end(), framebuffer) != mReadBack.end();
}

void Compositor::framebufferBound()
{
    if (mReadBack.empty() || !ready()) return;
    GLint framebuffer = 0;
    gRealGl.glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    mTracker.setDrawingData(readBack(framebuffer));
}

void Compositor::barrier()
{
    if (mHeld && !mHoldingBegin) flush();
}

void Compositor::clear(bool colour)
{
    barrier();
    if (colour) endOverlayRun();
    if (!colour || !ready()) return;
    GLint framebuffer = 0;
    gRealGl.glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &framebuffer);
    ++colourClearsOf(framebuffer);
    // A clear of every colour channel makes its rectangle fresh (alpha is no part of the
    // picture); a partial one draws nothing, and what it clears is background either way.
    if (!mTracker.colourMaskRgb()) return;
    constexpr int kAll = 1 << 30;
    mFresh.drawn = false;
    mFresh.framebuffer = framebuffer;
    mFresh.rect = mTracker.scissorTest() ? mTracker.scissor() : glm::ivec4(0, 0, kAll, kAll);
}

uint64_t& Compositor::colourClearsOf(GLint framebuffer)
{
    for (auto& [name, clears] : mColourClears) {
        if (name == framebuffer) return clears;
    }
    return mColourClears.emplace_back(framebuffer, 0).second;
}

void Compositor::backBufferShown()
{
    constexpr int kAll = 1 << 30;
    mFresh = Fresh{false, 0, glm::ivec4(0, 0, kAll, kAll)};
}

GLint Compositor::renderMode(GLenum mode)
{
    barrier();
    const GLint result = mNext.glRenderMode(mode);
    GLint now = GL_RENDER;
    gRealGl.glGetIntegerv(GL_RENDER_MODE, &now);
    mTracker.setRenderMode(GLenum(now));
    return result;
}

void Compositor::flush()
{
    // While the program compiles a display list, every command the styles issued would be
    // compiled into it (and, with GL_COMPILE, not drawn): what is held waits for the next
    // barrier after glEndList.
    if (mInFlush || mHoldingBegin || mTracker.compiling()) return;
    syncStream();
    if (!mHeld) {
        // Off or without styles nothing is held, and what the tracker kept is nobody's: it
        // must not join the scene of the next styled frame.
        if (mPhase == Phase::Ready && !(mEnabled && mHasStyles)) {
            mTracker.takeBatches(mTracked);
            mTracker.recycle(mTracked);
        }
        return;
    }
    mHeld = false;
    mInFlush = true;
    const auto start = std::chrono::steady_clock::now();
    mTracker.takeBatches(mTracked);
    buildScene();
    mHeldColoured = false;
    if (!mScene.objects.empty()) render();
    mFresh.drawn = true; // the styles' picture
    mFrameComposeMs +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    mInFlush = false;
}

void Compositor::buildScene()
{
    // The tracker's vertices are the reconstruction's: lent, not copied, and handed back
    // to the tracker's pool for the next frame.
    mBatches.resize(mTracked.size());
    for (size_t i = 0; i < mTracked.size(); ++i) {
        TrackedBatch& t = mTracked[i];
        reconstruct::Batch& b = mBatches[i];
        assignAssembly(b, t);
        // Translucent and alpha-tested surfaces are objects of their own (StyleChain::render),
        // also among those drawn without the depth test or depth writes (bzflag's cloud layer,
        // blended, joined the opaque ground drawn before it and covered its sky in white).
        const bool offset = t.offsetFactor != 0.0f || t.offsetUnits != 0.0f;
        const int look = t.translucent ? 1 : t.alphaFunc != GL_ALWAYS ? 2 : offset ? 4 : 0;
        b.pass = !t.depthTest                      ? 5 + 10 * look
                 : t.depthOnly                     ? 3
                 : !t.depthWrite && !t.translucent ? 6 + 10 * look
                                                   : look;
        b.vertices.swap(t.vertices);
        b.contentHash = t.contentHash != 0 ? t.contentHash : reconstruct::hashBatch(b);
    }
    // Last frame's scene lets go of its meshes first: an animated mesh is then updated in
    // place rather than copied (the Reconstructor copies a mesh someone else still holds).
    mScene.objects.clear();
    mReconstructor.build(mBatches, mObjects);
    for (size_t i = 0; i < mTracked.size(); ++i)
        mTracked[i].vertices.swap(mBatches[i].vertices);
    mTracker.recycle(mTracked);
    if (logEnabled(LogLevel::Debug)) {
        const reconstruct::CacheStats st = mReconstructor.cacheStats();
        NPRGL_DEBUG("flush %llu: %zu batches, %zu objects; cache hits %llu, updates %llu, "
                    "rebuilds %llu, evictions %llu, entries %zu, bytes %zu",
                    static_cast<unsigned long long>(mFlushes), mBatches.size(), mObjects.size(),
                    static_cast<unsigned long long>(st.hits),
                    static_cast<unsigned long long>(st.updates),
                    static_cast<unsigned long long>(st.rebuilds),
                    static_cast<unsigned long long>(st.evictions), st.entries, st.bytes);
    }
    for (const reconstruct::FrameObject& o : mObjects) {
        const TrackedBatch& t = mTracked[o.firstBatch];
        styles::SceneObject s;
        static_cast<styles::Appearance&>(s) = t; // the first batch's look is the object's
        s.mesh = o.mesh;
        s.modelview = o.modelview;
        s.lightDir = lightDirection(t);
        // What the object's other batches change in it. One cull state: its batches' when
        // they agree (the first batch's lost the others' faces where they did not). Where they
        // do not, no one state culls what each of them culled: the object is drawn whole, and
        // depth hides the back of a closed one as the culling did. And the finest cut of all.
        for (uint32_t b = 1; b < o.batchCount; ++b) {
            const TrackedBatch& other = mTracked[o.firstBatch + b];
            if (other.culled != t.culled) s.culled = 0;
            const float f = other.cutFeature;
            if (f > 0.0f && (s.cutFeature == 0.0f || f < s.cutFeature)) s.cutFeature = f;
        }
        textureRuns(o, s);
        s.id = uint32_t(mScene.objects.size() + 1);
        mScene.objects.push_back(std::move(s));
    }
    if (!mTracked.empty()) mScene.viewport = mTracked.back().viewport;
    mScene.frame = mContext.frame();
    mScene.framebuffer = uint32_t(mHeldFramebuffer);
    mScene.scissored = mHeldScissorTest;
    mScene.scissor = mHeldScissor;
    mScene.depthRange = mHeldDepthRange;
    mScene.alphaWrites = !mHeldColoured || mHeldAlphaWrites;
    mScene.colourClears = colourClearsOf(mHeldFramebuffer);
    mScene.copiedToTexture = mCopyFlush || copiedRecently(mHeldFramebuffer, mScene.viewport);
    // Fresh when the cleared (or shown) rectangle holds the scene's viewport, as confined.
    const glm::ivec4 area = mScene.confined(mScene.viewport);
    const glm::ivec4& fresh = mFresh.rect;
    mScene.colourFresh = !mFresh.drawn && mFresh.framebuffer == mHeldFramebuffer &&
                         area.x >= fresh.x && area.y >= fresh.y &&
                         int64_t(area.x) + area.z <= int64_t(fresh.x) + fresh.z &&
                         int64_t(area.y) + area.w <= int64_t(fresh.y) + fresh.w;
}

void Compositor::textureRuns(const reconstruct::FrameObject& o, styles::SceneObject& s) const
{
    // Each batch keeps its own texture: its faces are a run in the mesh's face order.
    const std::vector<uint32_t>& ends = o.mesh->updateState.batchFaceEnd;
    bool mixed = false;
    for (uint32_t b = 1; b < o.batchCount; ++b) {
        const TrackedBatch& t = mTracked[o.firstBatch + b];
        mixed = mixed || t.texture != s.texture || t.lightmap != s.lightmap;
    }
    if (!mixed || ends.size() != o.batchCount) return;
    uint32_t first = 0;
    for (uint32_t b = 0; b < o.batchCount; ++b) {
        const GLuint texture = mTracked[o.firstBatch + b].texture;
        const GLuint lightmap = mTracked[o.firstBatch + b].lightmap;
        const uint32_t end = ends[b];
        if (end <= first) continue; // a batch whose faces all fell out (degenerate)
        if (!s.textureRuns.empty() && s.textureRuns.back().texture == texture &&
            s.textureRuns.back().lightmap == lightmap) {
            s.textureRuns.back().faceCount = end - s.textureRuns.back().firstFace;
        } else {
            s.textureRuns.push_back({first, end - first, texture, lightmap});
        }
        first = end;
    }
}

void Compositor::render()
{
    OwnGlCalls own;
    if (mSaved.save()) {
        GLint current = 0;
        gRealGl.glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &current);
        if (current != mHeldFramebuffer) mBindFramebuffer(GL_DRAW_FRAMEBUFFER, mHeldFramebuffer);
        gRealGl.glGetFloatv(GL_COLOR_CLEAR_VALUE, glm::value_ptr(mScene.clearColor));
        // A scene read back is drawn as the program drew it: without a shading style the
        // program's own draws are there already, and no style goes over them.
        if (!mPlainFlush)
            mChain.render(mScene);
        else if (mShading && !mChain.renderPlain(mScene))
            mChain.render(mScene);
        mSaved.restore();
    } else if (!mStackWarned) {
        // The tracker holds nothing while the stacks are full, so only a program that
        // overflowed them (a GL error of its own) gets here.
        NPRGL_WARN("context %u: the attribute stacks are full although nprgl counted room; "
                   "held-back geometry of this frame is not drawn",
                   mContext.serial());
        mStackWarned = true;
    }
    ++mFlushes;
    const GLenum ours = own.finish();
    static bool reported = false;
    if (ours != GL_NO_ERROR && !reported) {
        NPRGL_DEBUG("a style left GL error 0x%x (not the program's)", ours);
        reported = true;
    }
}

} // namespace nprgl
