#pragma once

#include "frame/DrawCounts.h"
#include "frame/OverlayContrast.h"
#include "frame/SavedGlState.h"
#include "frame/ScenePick.h"
#include "frame/StateTracker.h"
#include "reconstruct/Reconstructor.h"
#include "shim/Api.h"
#include "styles/Scene.h"
#include "styles/StyleChain.h"

#include <atomic>
#include <map>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace nprgl {

class Context;
class Recorder;

// The frame compositor (docs/architecture.md), one per GL context when a style is active.
//
// The StateTracker follows the context's Stream (recorded in memory by the Recorder) and is
// brought up to date at every draw. A polygonal 3D draw in plain state is held back: its
// geometry joins the frame's scene and the driver never draws it (glBegin..glEnd and array
// draws are only recorded; a display list still runs, for its state changes, with the
// rasteriser discarding its primitives). Everything else is forwarded in order. A barrier —
// a forwarded draw after held ones, a clear, a read-back, a copy, a change of framebuffer or
// viewport, a frame end, a context switch — flushes the scene: reconstruct it, save all of
// the program's state, run the style chain (whose shading style draws the scene and its
// depth, so later forwarded drawing depth-tests against it), restore the state, and keep the
// program's pending GL error for its next glGetError. With no shading style in the chain
// the held draws go to the driver as they are and the outline styles draw over the
// program's own picture.
class Compositor {
public:
    Compositor(Context& ctx, Recorder& recorder);
    ~Compositor();

    // Points the dispatch slots the compositor needs at its own functions; the previous
    // slots (recording functions) are what they call next.
    void install(GlDispatch& dispatch);
    // Points `dispatch`'s glEnd at the compositor's (the table of an open held glBegin).
    static void installEnd(GlDispatch& dispatch);
    // Work the styles do off the frame (the textures' abstractions) is done at once instead:
    // a replay's pictures must not depend on timing.
    static void finishStyleWorkAtOnce();

    // The Recorder's hooks: the tracker consumes a glBegin..glEnd before the recorder
    // replaces it with a blob reference, and restarts when the Stream is cleared.
    void syncStream();
    void streamRewritten(size_t size) { mSynced = size; }
    void streamCleared() { mSynced = 0; }
    // A large argument the Recorder stored as a blob: kept until the tracker has read it.
    void keepBlob(uint64_t hash, const void* data, size_t size);

    // Renders what is held back, if anything.
    void flush();

    // At a frame end: from the next frame on, run `settings` (a chain without styles passes
    // every draw through); the chain is rebuilt in this context with one log line.
    // `announce`: say so in the log (the overlay's slider drags say it once, when let go).
    void restyle(const StyleSettings& settings, bool announce = true);
    const StyleSettings& settings() const { return mSettings; }
    // Styling off shows the program's own picture (for comparison); on again restyles it.
    void setEnabled(bool enabled);
    bool enabled() const { return mEnabled; }
    // At a frame end: the frame's counts become lastFrameCounts(), the next frame's start.
    void endFrameCounts();
    const DrawCounts& lastFrameCounts() const { return mLastFrameCounts; }
    const DrawCounts& runCounts() const { return mRunCounts; }
    // The textures the chain drew as drawings so far, and those it left, by reason.
    const styles::AbstractTextures::Counts& textureCounts() const
    {
        return mChain.textureCounts();
    }
    // Logs the run's counts, once: when the context goes, or at exit for a context the
    // program never destroyed (most programs just exit). On the context's thread, or where
    // no thread has it current.
    void reportRunCounts();
    // At exit, for a context current on another thread (which may be drawing with it): the
    // run's counts as they stood at its last frame end, once.
    void reportRunCountsAtFrameEnd();
    // The object of the last flush under window pixel (x, y), y from the window's top: for
    // the overlay's pick. PickResult::texture's content hash in `textureHash`.
    PickResult pick(int x, int y, int windowHeight, uint64_t& textureHash) const;
    // Rules (leave_texture, leave_state): the draws they name are left from now on.
    void setRules(LeaveRules rules) { mTracker.setRules(std::move(rules)); }
    const LeaveRules& rules() const { return mTracker.rules(); }
    // The last frame's time in the compositor (reconstruction and styles), in ms.
    double lastFrameComposeMs() const { return mLastFrameComposeMs; }
    // A GL error of the program's that nprgl took while drawing its own things (the
    // overlay): the program's next glGetError answers it (Context::keepProgramError).
    void keepProgramError(GLenum error);
    // When the context is first current: one that the styles cannot draw in (OpenGL ES, a
    // core profile, GL older than 3.0) is passed through from now on, and said so.
    void checkContext();

    // Dispatch entry points (through the current context's compositor).
    void begin(GLenum mode);
    void end();
    // Where a draw issued now goes: held for the styles, a possible layer over held geometry
    // (array draws and glBegin; `layers`), or left to the driver (counted, with a flush first
    // when a scene is held).
    enum class Placement { Held, Layer, Left };
    Placement placeDraw(GLenum mode, bool layers);
    // After a Layer draw was recorded only (the stream was `mark` bytes long before it): what
    // the caller does with it. Merged into its object (counted styled): not drawn, unless the
    // chain has no shading style (the program draws its objects). Left (counted, the scene
    // flushed first): drawn, tinted by the coverage style. Drawn: the driver drew it already.
    enum class Settled { Merged, Draw, Drawn };
    Settled settleLayer(size_t mark);
    size_t streamSize() const;
    void callList(GLuint list);
    bool holdLists(GLsizei n, GLenum type, const void* lists);
    // Rasteriser discard around a held display list (its state changes must still run).
    void mask();
    void unmask();
    // The chain has a shading style: held draws are drawn by it, not by the driver.
    bool shading() const { return mShading; }
    const GlDispatch& heldNext() const { return mHeldNext; }
    void barrier();
    // Before the program's glReadPixels (see mReadBack).
    void readPixels();
    // Before the program copies the framebuffer into a texture (Scene::copiedToTexture).
    void copyToTexture();
    // After the program bound a framebuffer: tells the tracker whether it draws data.
    void framebufferBound();
    // A clear of the colour buffer (colour) or of others: a barrier, counted.
    void clear(bool colour);
    // The program drew into a colour buffer other than through a held draw (glDrawPixels,
    // glBitmap, a blit...; tintBegin says so for the draws left to the driver).
    void colourDrawn() { mFresh.drawn = true; }
    // The window's back buffer was shown: its contents are undefined from now on, so what
    // nothing draws over in the next frame is background.
    void backBufferShown();
    // Around a draw left as the program draws it: with the coverage style, paints it red;
    // on a page, a glow is drawn as ink. list: the display list the draw calls, if any.
    void tintBegin(GLuint list = 0);
    void tintEnd();
    // With OverlayContrast enabled (a replay's --overlays, CompositorOverlays.cpp): around a
    // draw left as the program draws it and around glBitmap and glDrawPixels, a 2D draw into
    // the window is measured; any other draw, a clear or a blit ends the run of 2D draws.
    void overlayBegin();
    void overlayEnd();
    void endOverlayRun() { mOverlays.endRun(); }
    // The 2D draws measured since the last call (OverlayContrast::takeFrame).
    std::vector<OverlayContrast::Draw> takeOverlays() { return mOverlays.takeFrame(); }
    GLint renderMode(GLenum mode);
    const GlDispatch& next() const { return mNext; }

private:
    bool ready();
    // placeDraw for a glCallList (a list is a Layer when it may be a pass).
    Placement placeList(GLuint list);
    void noteMerged(uint64_t passes);
    bool startStyles();
    // Shuts the chain down (when it ran) and starts mSettings' chain, with the program's
    // state and pending GL error kept; false with a message when it cannot start.
    bool startChain(bool restart, std::string& error);
    // A draw measured as a 2D overlay now; at a draw's placement, ends the run if not.
    bool overlayMeasurable();
    void overlayPlaced();
    void noteHeld();
    void noteLayers();
    void noteUnstyled(bool polygonal);
    void noteLeft(const char* why);
    void buildScene();
    // The object's texture per batch as runs of faces (SceneObject::textureRuns).
    void textureRuns(const reconstruct::FrameObject& o, styles::SceneObject& s) const;
    void render();

    Context& mContext;
    Recorder& mRecorder;
    GlDispatch mNext{};
    StateTracker mTracker;
    class Blobs : public BlobSource {
    public:
        const std::vector<uint8_t>* blob(uint64_t hash, std::string& error) override;
        std::map<uint64_t, std::vector<uint8_t>> kept;
    } mBlobs;
    size_t mSynced = 0;
    bool mBroken = false; // the Stream could not be followed: passthrough from then on

    enum class Phase { Unknown, Ready, Off };
    Phase mPhase = Phase::Unknown;
    styles::StyleChain mChain;
    StyleSettings mSettings; // what the chain runs: the context's, then each restyle's
    bool mHasStyles = true;  // mSettings names at least one style
    bool mEnabled = true;    // styling on (the toggle key)
    bool mShading = true;
    bool mTintLeft = false; // the chain has the coverage style
    bool mLeftNow = false;  // the draw being forwarded was counted as left
    bool mTinting = false;
    bool mGlowing = false; // a left glow is being drawn as ink on the chain's page
    bool mGlowSaid = false;
    bool mMixedGlowSaid = false;
    uint32_t mLayersSaid = 0;    // texture units whose dropped layers were said
    uint32_t mLightmapsSaid = 0; // texture units whose lightmaps were said
    GlDispatch mHeldNext{};      // mNext with draws and vertices recorded only
    GlDispatch mHeldTable{};     // the context's table while a held glBegin..glEnd is open

    bool mHeld = false;         // held batches wait for the next flush
    bool mHoldingBegin = false; // inside a held glBegin..glEnd
    static constexpr size_t kNoLayer = SIZE_MAX;
    size_t mLayerMark = kNoLayer;     // stream size at a possible layer's glBegin
    std::vector<uint8_t> mLayerCalls; // its calls, for the driver when it is not merged
    const char* mLayerWhy = nullptr;  // why a possible layer would be left
    bool mReplaySaid = false;
    GLboolean mSavedDiscard = GL_FALSE;
    bool mStackWarned = false;
    GLint mHeldFramebuffer = 0;
    bool mHeldScissorTest = false; // the held scene's scissor test and box
    glm::ivec4 mHeldScissor{0};
    glm::vec2 mHeldDepthRange{0.0f, 1.0f};
    bool mHeldColoured = false;   // a draw with colour is held: mHeldAlphaWrites is its mask
    bool mHeldAlphaWrites = true; // the held draws write alpha (glColorMask's fourth)
    bool mInFlush = false;
    // 3D polygon draws (a glBegin/glEnd, an array draw, a held glCallList) over the run and
    // in this frame: styled, and left as the program draws them by reason (each reason said
    // at its first).
    DrawCounts mRunCounts, mFrameCounts, mLastFrameCounts;
    // Logs `counts` (the run's, or their copy at a frame end) and the textures drawn as
    // drawings, with `note` after, once.
    void report(const DrawCounts& counts, const styles::AbstractTextures::Counts& textures,
                const char* note);
    // mRunCounts at the last frame end, for a thread that may not read mRunCounts itself.
    std::mutex mFrameEndCountsMutex;
    DrawCounts mFrameEndCounts;
    styles::AbstractTextures::Counts mFrameEndTextures;
    std::atomic<bool> mRunCountsReported{false};
    uint64_t mMergedSeen = 0; // the tracker's merged passes already counted
    bool mMergeSaid = false;
    double mFrameComposeMs = 0.0, mLastFrameComposeMs = 0.0;

    std::vector<TrackedBatch> mTracked;
    std::vector<reconstruct::Batch> mBatches;
    std::vector<reconstruct::FrameObject> mObjects;
    reconstruct::Reconstructor mReconstructor;
    styles::Scene mScene;
    uint64_t mFlushes = 0;
    // Per framebuffer, the glClear / glClearBuffer calls that reached its colour (another
    // framebuffer's clear makes no new background here: dreamchess clears its picking
    // target, and its scene's page was laid again over its black sky).
    std::vector<std::pair<GLint, uint64_t>> mColourClears;
    uint64_t& colourClearsOf(GLint framebuffer);
    // Framebuffer objects the program read back with glReadPixels: their pixels are data, so
    // draws into them are left as drawn; the flush its first read forces is drawn unstyled.
    std::vector<GLint> mReadBack;
    bool mPlainFlush = false;
    bool mCopyFlush = false; // the flush under way is for a glCopyTex* (copyToTexture)
    // Where the program copied its drawing into a texture (glCopyTex*) in the last few frames
    // (a frame may end at a glFinish as well as at the swap): a flush there is that
    // texture's content too, though another barrier (a draw the styles leave) came first.
    // Programs render their textures the same way every frame.
    static constexpr uint64_t kCopyMemory = 4;
    struct Copied {
        GLint framebuffer = 0;
        glm::ivec4 viewport{0};
        uint64_t frame = 0;
    };
    std::vector<Copied> mCopied;
    bool copiedRecently(GLint framebuffer, const glm::ivec4& viewport) const;
    bool readBack(GLint framebuffer) const;
    // Where one framebuffer's colour holds nothing drawn since it was cleared or shown
    // (Scene::colourFresh): its window rectangle, unless something drew since.
    struct Fresh {
        bool drawn = true;
        GLint framebuffer = 0;
        glm::ivec4 rect{0};
    } mFresh;

    SavedGlState mSaved; // the program's state while the chain starts or renders
    OverlayContrast mOverlays;
    bool mMeasuring = false; // overlayBegin read the window for the draw under way
    PFNGLBINDFRAMEBUFFERPROC mBindFramebuffer = nullptr;
};

} // namespace nprgl
