#pragma once

#include "styles/Style.h"
#include "styles/StyleSettings.h"
#include "styles/background/GlowInk.h"
#include "styles/shading/PlainShading.h"
#include "styles/textures/AbstractTextures.h"

#include <memory>
#include <string>
#include <vector>

namespace nprgl::styles {

// The styles of one chain in one GL context: created and initialised on first use, run in
// order (the shading style first, then the background, then the outline styles as named)
// with the baseline state of Style.h set before each.
class StyleChain {
public:
    // getProc resolves the real driver's entry points. False with a message when the driver
    // lacks what the styles need or no style of the chain could start.
    bool init(const StyleSettings& settings, GlFunctions::GetProc getProc, std::string& error);
    // Renders the scene. The caller has saved the program's state and restores it after.
    void render(const Scene& scene);
    // Renders the scene without styles, as the program drew it (PlainShading), for a scene
    // whose pixels the program reads back as data. False when that cannot be drawn.
    bool renderPlain(const Scene& scene);
    void shutdown();

    bool hasShading() const { return mHasShading; }
    // The chain draws a light page (a background style): additive glows of the program's
    // would wash out on it, so they are drawn as ink around their draws (GlowInk). On a dark
    // page they add light as the program draws them.
    bool inksGlows() const { return mGlowInkReady && !mContext.page.dark(); }
    void glowBegin(bool textured, bool sourceAlpha, GLenum fogMode)
    {
        mGlowInk.begin(mContext.gl, textured, sourceAlpha, fogMode);
    }
    void glowEnd() { mGlowInk.end(mContext.gl); }
    StyleContext& context() { return mContext; }
    // The program's textures drawn as drawings so far, and those left as the program's.
    const AbstractTextures::Counts& textureCounts() const { return mAbstractions.counts(); }

    // paper.tone, or what the chain's paper colour and styles ask of the page.
    PageTone::Mode pageMode() const;
    // Sets the baseline state of Style.h: the shading pass's, or the one of the passes after.
    void setBaseline(const Scene& scene, bool shadingPass = false);

private:
    StyleSettings mSettings;
    StyleContext mContext;
    AbstractTextures mAbstractions; // the program's textures as drawings
    std::vector<std::unique_ptr<Style>> mStyles;
    std::vector<size_t> mBackgrounds; // indices in mStyles of the background styles
    bool mHasShading = false;
    GlowInk mGlowInk;
    bool mGlowInkReady = false;
    PlainShading mPlain;
    enum class PlainState { Unbuilt, Ready, Failed } mPlainState = PlainState::Unbuilt;
    // The object's alpha test and polygon offset, as the program drew it (a run's first).
    void applyTestAndOffset(const SceneObject& o);
    // `part`'s objects in runs of equal draw state (depth test and writes, translucency,
    // alpha test, offset), each from the baseline with its alpha test and offset applied:
    // draw(run, first) sets the rest and renders (run: mRun, or `part` when it is one run);
    // test and offset are undone after.
    template <typename Draw> void forEachRun(const Scene& part, Draw&& draw);
    // The depth test (depth-tested objects by `testedFunc`), depth writes and blending a run
    // is drawn with as the program drew it; the caller disables blending after.
    void setDrawnState(const SceneObject& first, GLenum testedFunc);
    // The shading style alone draws `part`'s objects with the program's depth test, depth
    // writes and blending.
    void renderAsDrawn(const Scene& part);
    // The shading style's pass over the opaque scene, which lays its depth.
    void renderShading(const Scene& part, Style& shading);
    // The shading style draws `part`'s objects into depth alone (its colour mask off).
    void renderDepthOnly(const Scene& part);
    // The shading style's pass over translucent objects, blended by their alpha.
    void renderBlended(const Scene& part);
    // Whether the flush has cut-outs a style of the chain outlines (then mWithCutOuts holds
    // them after the opaque scene).
    bool collectCutOuts();

    Scene mOpaque, mCutOut, mDepthOnly, mTranslucent, mRun; // render()'s parts, kept
    Scene mDepthOnlyFirst;   // depth-only objects drawn before every coloured one
    Scene mBlendedCutOut;    // translucent, shaped by their alpha test and depth writes
    Scene mWithCutOuts;      // the opaque scene and the cut-outs (Style::outlinesCutOuts)
    Scene mBackdrop, mOnTop; // drawn as the program did, before or after the scene
};

} // namespace nprgl::styles
