#include "styles/StyleChain.h"

#include "common/Log.h"
#include "styles/StyleRegistry.h"
#include "styles/background/PaperStyle.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace nprgl::styles {

namespace {

// Whether every vertex of the object lies at the far plane (a backdrop quad drawn at z = 1
// in NDC with the depth test on, as xscreensaver's atlantis draws its water): its pixels keep
// the cleared depth, so a page laid where that depth remains would cover it. Most objects
// answer at their first vertex.
bool atFarPlane(const SceneObject& o)
{
    if (!o.mesh || o.mesh->faceCorners.empty()) return false;
    const glm::mat4 m = o.projection * o.modelview;
    for (uint32_t corner : o.mesh->faceCorners) {
        const glm::vec4 c = m * glm::vec4(o.mesh->sourceVertices[corner].position, 1.0f);
        // Rounds to the cleared depth of 24 bits (1e-6 in NDC: a few of its steps).
        if (!(c.w > 0.0f) || !(c.z >= (1.0f - 1e-6f) * c.w)) return false;
    }
    return true;
}

} // namespace

PageTone::Mode StyleChain::pageMode() const
{
    // The page's tone is the chain's, not only the paper's: without paper the program's own
    // background stays, and the ink must still stand out on it.
    const auto mode = PageTone::Mode(std::clamp(int(std::lround(mContext.param("paper", "tone"))),
                                                0, int(PageTone::Mode::Dark)));
    if (mode != PageTone::Mode::Auto) return mode;
    // A page colour the user chose (a preset's blue blueprint paper) is the page: its own
    // lightness decides the ink.
    glm::vec3 colour(1.0f);
    if (PaperStyle::colourConfigured(mContext, colour)) {
        return PageTone::luminance(colour) < 0.5f * (PageTone::kDarkBelow + PageTone::kLightAbove)
                   ? PageTone::Mode::Dark
                   : PageTone::Mode::Light;
    }
    const auto& chain = mSettings.chain();
    if (std::any_of(chain.begin(), chain.end(), [](const StyleInfo* s) { return s->lightPage; })) {
        return PageTone::Mode::Light;
    }
    return mode;
}

bool StyleChain::init(const StyleSettings& settings, GlFunctions::GetProc getProc,
                      std::string& error)
{
    mSettings = settings;
    mContext.settings = &mSettings;
    mContext.abstractions = &mAbstractions;
    mHasShading = false; // a chain may be started again with other settings
    std::string missing;
    if (!mContext.gl.load(getProc, missing)) {
        error = "the driver lacks " + missing;
        return false;
    }
    const GlFunctions& gl = mContext.gl;
    gl.GenVertexArrays(1, &mContext.vao);
    mContext.page.setMode(pageMode());
    // Shading first, then the background (it must see the shaded surfaces' colours and
    // lie under the ink), then the outline styles in the order named.
    std::vector<const StyleInfo*> order = mSettings.chain();
    std::stable_sort(order.begin(), order.end(), [](const StyleInfo* a, const StyleInfo* b) {
        return int(a->role) < int(b->role);
    });
    for (const StyleInfo* info : order) {
        if (!info->create) continue;
        std::unique_ptr<Style> style = info->create();
        std::string why;
        if (!style || !style->init(mContext, why)) {
            NPRGL_ERROR("style %s cannot run here (%s); it is left out", info->name.c_str(),
                        why.c_str());
            if (style) style->shutdown(mContext);
            continue;
        }
        mHasShading = mHasShading || info->role == StyleRole::Shading;
        if (info->role == StyleRole::Background) mBackgrounds.push_back(mStyles.size());
        mStyles.push_back(std::move(style));
        if (info->role == StyleRole::Background && !mGlowInkReady) {
            std::string inkError;
            mGlowInkReady = mGlowInk.init(gl, inkError);
            if (!mGlowInkReady) {
                NPRGL_WARN("additive glows cannot be inked on the page here (%s): they may wash "
                           "out", inkError.c_str());
            }
        }
    }
    // Whatever the styles' set-up left in the error flag is theirs, not the program's.
    while (gl.GetError() != GL_NO_ERROR) {
    }
    if (mStyles.empty()) {
        error = "no style of '" + mSettings.chainName() + "' could start";
        return false;
    }
    return true;
}

void StyleChain::setBaseline(const Scene& scene, bool shadingPass)
{
    const GlFunctions& gl = mContext.gl;
    gl.BindVertexArray(mContext.vao);
    gl.UseProgram(0);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.Viewport(scene.viewport.x, scene.viewport.y, scene.viewport.z, scene.viewport.w);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthMask(GL_TRUE);
    // The program's: the scene's depth is where its later drawing expects it.
    gl.DepthRange(double(scene.depthRange.x), double(scene.depthRange.y));
    gl.PolygonOffset(-1.0f, -1.0f);
    // The shading pass lays down the scene's depth; the passes after it draw onto it.
    gl.DepthFunc(shadingPass ? GL_LESS : GL_LEQUAL);
    if (shadingPass) gl.Disable(GL_POLYGON_OFFSET_FILL);
    else gl.Enable(GL_POLYGON_OFFSET_FILL);
    mContext.endScissor(scene);
    for (GLenum cap : {GL_BLEND, GL_CULL_FACE, GL_STENCIL_TEST, GL_ALPHA_TEST, GL_LIGHTING,
                       GL_TEXTURE_2D, GL_FOG, GL_LINE_SMOOTH, GL_POLYGON_SMOOTH,
                       GL_POLYGON_OFFSET_LINE, GL_POLYGON_OFFSET_POINT, GL_COLOR_LOGIC_OP}) {
        gl.Disable(cap);
    }
    gl.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    // The styles' front: gl_FrontFacing and culling are by it, not by the program's front face
    // at the flush (FaceCulling, ShadingCommon's faceSign).
    gl.FrontFace(GL_CCW);
    mContext.alphaWrites = scene.alphaWrites;
    mContext.colourMaskOn();
    gl.LineWidth(1.0f);
    gl.PointSize(1.0f);
}

template <typename Draw>
void StyleChain::forEachRun(const Scene& part, Draw&& draw)
{
    auto same = [](const SceneObject& a, const SceneObject& b) {
        return a.depthTest == b.depthTest && a.depthWrite == b.depthWrite &&
               a.depthAlways == b.depthAlways && a.depthFunc == b.depthFunc &&
               a.translucent == b.translucent && a.alphaFunc == b.alphaFunc &&
               a.alphaRef == b.alphaRef && a.offsetFactor == b.offsetFactor &&
               a.offsetUnits == b.offsetUnits;
    };
    const GlFunctions& gl = mContext.gl;
    for (size_t i = 0; i < part.objects.size();) {
        const SceneObject& first = part.objects[i];
        size_t end = i + 1;
        while (end < part.objects.size() && same(part.objects[end], first)) ++end;
        // One run is the whole part (the common case): drawn as it is, not copied.
        const bool whole = i == 0 && end == part.objects.size();
        if (!whole) {
            mRun.objects.assign(part.objects.begin() + long(i), part.objects.begin() + long(end));
        }
        const Scene& run = whole ? part : mRun;
        setBaseline(run, true);
        applyTestAndOffset(first);
        draw(run, first);
        gl.Disable(GL_ALPHA_TEST);
        gl.Disable(GL_POLYGON_OFFSET_FILL);
        i = end;
    }
}

void StyleChain::render(const Scene& scene)
{
    // The opaque scene goes through the whole chain; the translucent objects then through the
    // shading style alone, in the program's order, blended over everything (outlines and the
    // page included), as the program blends them over its own picture.
    // Alpha-tested objects and decals are shaded with the program's alpha test and polygon
    // offset and left out of the styles after the shading (their edges are not their
    // cut-outs' edges; a decal's would fight its surface's).
    // The window's background decides the page (an offscreen target's clear is a texture's).
    if (scene.framebuffer == 0) mContext.page.observe(scene.frame, glm::vec3(scene.clearColor));
    mContext.frame = scene.frame;
    mOpaque.objects.clear();
    mTranslucent.objects.clear();
    mCutOut.objects.clear();
    mBlendedCutOut.objects.clear();
    mDepthOnly.objects.clear();
    mDepthOnlyFirst.objects.clear();
    mBackdrop.objects.clear();
    mOnTop.objects.clear();
    bool depthTested = false; // an object drawn with the depth test came before
    for (const SceneObject& o : scene.objects) {
        // Drawn without the depth test or, opaque, without depth writes: skies, clouds and
        // scenery behind the scene (before its first object), marks over it (after): drawn as
        // the program drew them, so they neither hide nor cover what they should not. Without
        // the shading style the program draws them itself; they get no lines.
        // Unlit by the program, they are shaded in an even light (a sky box's faces would
        // otherwise fall into the shadow band by the head-light).
        if (!o.depthTest || (!o.depthWrite && !o.translucent && !o.depthOnly)) {
            if (!mHasShading) continue;
            Scene& part = depthTested ? mOnTop : mBackdrop;
            part.objects.push_back(o);
            part.objects.back().flatLight = o.lights.count == 0;
            continue;
        }
        depthTested = true;
        if (o.depthOnly) {
            // Where the program draws it: before every coloured object (an occluder, a
            // pre-pass) it goes first and hides what the program draws behind it; after some
            // (a mask over the ground drawn before it), after the opaque scene, so that it
            // does not fight the surfaces drawn before it at their depth.
            const bool first = mOpaque.objects.empty() && mTranslucent.objects.empty() &&
                               mCutOut.objects.empty() && mBlendedCutOut.objects.empty();
            if (mHasShading) (first ? mDepthOnlyFirst : mDepthOnly).objects.push_back(o);
        } else if (!mHasShading) {
            mOpaque.objects.push_back(o);
        } else if (o.translucent) {
            // Blended but with its depth written where the alpha test keeps it, and a texture
            // whose cut is known (foliage with soft rims; or one the test keeps whole, a mostly
            // opaque surface): its shape is that cut, and it is drawn with the cut-outs, before
            // the outlines, which then lie over it as over them. Not a surface faded as a whole
            // by its colours (3D text fading out: its cut is then not known), nor a decal.
            const bool shaped =
                o.alphaFunc != GL_ALWAYS && o.cutFeature > 0.0f && o.depthWrite && !o.lifted();
            (shaped ? mBlendedCutOut : mTranslucent).objects.push_back(o);
        } else {
            (o.special() ? mCutOut : mOpaque).objects.push_back(o);
        }
    }
    for (Scene* part : {&mOpaque, &mTranslucent, &mCutOut, &mBlendedCutOut, &mDepthOnly,
                        &mDepthOnlyFirst, &mRun,
                        &mBackdrop, &mOnTop}) {
        part->takeFrameOf(scene);
    }
    const bool outlineCutOuts = collectCutOuts();
    // The page under everything: a backdrop in the clear colour, drawn without depth (a dark
    // floor), stays the program's and does not become page. Without a backdrop it is laid
    // after the opaque scene (the background style's render), where the scene's depth
    // rejects its pixels before any of the page's work, but not over what goes at the far
    // plane (a sky in a depth range of its own, a backdrop drawn at the far plane).
    const bool layLater =
        mBackdrop.objects.empty() && scene.depthRange.x < 1.0f &&
        std::none_of(mOpaque.objects.begin(), mOpaque.objects.end(), atFarPlane);
    for (size_t i : mBackgrounds) {
        setBaseline(scene, i == 0 && mHasShading);
        if (layLater) mStyles[i]->keepBackground(scene, mContext);
        else mStyles[i]->layBackground(scene, mContext);
    }
    renderAsDrawn(mBackdrop);
    // Depth-only objects the program draws before its coloured ones (an occluder, a depth
    // pre-pass) before the scene: what the program draws behind them stays hidden
    // (razzledazzle's ship, drawn into depth alone, hides the sky and sea drawn after it and
    // shows its pattern through; drawn after the scene it hid nothing). A colour pass over a
    // pre-pass ties in depth, as the program's does: the program's GL_LEQUAL or GL_EQUAL
    // lets it through (renderShading), drawn by the same shaders to the same depth.
    renderDepthOnly(mDepthOnlyFirst);
    for (size_t i = 0; i < mStyles.size(); ++i) {
        const bool shading = mHasShading && i == 0; // the shading style is ordered first
        if (shading) {
            renderShading(mOpaque, *mStyles[i]);
        } else if (outlineCutOuts && mStyles[i]->outlinesCutOuts()) {
            setBaseline(mWithCutOuts, false);
            mStyles[i]->render(mWithCutOuts, mContext);
        } else if (!mOpaque.objects.empty()) {
            setBaseline(mOpaque, false);
            mStyles[i]->render(mOpaque, mContext);
        }
        if (!shading) continue;
        forEachRun(mCutOut, [&](const Scene& run, const SceneObject&) {
            mStyles[i]->render(run, mContext);
        });
        renderBlended(mBlendedCutOut);
    }
    // Under the translucent objects and marks even when the flush has no opaque scene (laid
    // already otherwise: a second call does nothing).
    if (layLater) {
        for (size_t i : mBackgrounds) {
            setBaseline(scene, false);
            mStyles[i]->layBackground(scene, mContext);
        }
    }
    renderAsDrawn(mOnTop);
    renderDepthOnly(mDepthOnly);
    renderBlended(mTranslucent);
    mContext.meshes.endFlush(mContext.gl);
}

void StyleChain::renderDepthOnly(const Scene& part)
{
    if (part.objects.empty()) return;
    setBaseline(part, true);
    mContext.gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    mStyles.front()->render(part, mContext);
    mContext.colourMaskOn();
}

void StyleChain::renderBlended(const Scene& part)
{
    // With the program's depth writes, alpha test and offset: a translucent decal (a goal
    // painted on the floor) keeps the offset that lifts it off its surface.
    const GlFunctions& gl = mContext.gl;
    forEachRun(part, [&](const Scene& run, const SceneObject& first) {
        gl.Enable(GL_BLEND);
        gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        gl.DepthMask(first.depthWrite ? GL_TRUE : GL_FALSE);
        // A layer over a surface drawn before (water or paint through a texture's alpha)
        // passes at its depth, as the program's test lets it.
        if (first.depthFunc == GL_LEQUAL || first.depthFunc == GL_EQUAL) {
            gl.DepthFunc(GL_LEQUAL);
        }
        mStyles.front()->render(run, mContext);
    });
    gl.Disable(GL_BLEND);
}

bool StyleChain::collectCutOuts()
{
    // Alpha-tested objects and objects pushed back by a polygon offset, not decals (their
    // lines would fight their surfaces'), after the opaque scene; only for a chain with a
    // style that outlines them. Blended ones too where they write their depth
    // (mBlendedCutOut).
    mWithCutOuts.objects.clear();
    const bool asked = std::any_of(mStyles.begin(), mStyles.end(),
                                   [](const auto& style) { return style->outlinesCutOuts(); });
    if (!asked) return false;
    for (const SceneObject& o : mCutOut.objects) {
        if (!o.lifted()) mWithCutOuts.objects.push_back(o);
    }
    for (const SceneObject& o : mBlendedCutOut.objects) mWithCutOuts.objects.push_back(o);
    if (mWithCutOuts.objects.empty()) return false;
    mWithCutOuts.objects.insert(mWithCutOuts.objects.begin(), mOpaque.objects.begin(),
                                mOpaque.objects.end());
    mWithCutOuts.takeFrameOf(mOpaque);
    return true;
}

void StyleChain::renderShading(const Scene& part, Style& shading)
{
    // The program's rule for a tie in depth: under GL_LEQUAL (or GL_EQUAL) a surface drawn
    // later at the same depth covers the earlier one (a panel's face over its frame, a layer
    // painted on in the same plane), under GL_LESS the earlier one stays. The opaque scene's
    // objects differ in no other state forEachRun tells apart.
    forEachRun(part, [&](const Scene& run, const SceneObject& first) {
        if (first.depthFunc == GL_LEQUAL || first.depthFunc == GL_EQUAL) {
            mContext.gl.DepthFunc(GL_LEQUAL);
        }
        shading.render(run, mContext);
    });
}

void StyleChain::applyTestAndOffset(const SceneObject& o)
{
    const GlFunctions& gl = mContext.gl;
    if (o.alphaFunc != GL_ALWAYS) {
        gl.Enable(GL_ALPHA_TEST);
        gl.AlphaFunc(o.alphaFunc, o.alphaRef);
    }
    if (o.offsetFactor != 0.0f || o.offsetUnits != 0.0f) {
        gl.Enable(GL_POLYGON_OFFSET_FILL);
        gl.PolygonOffset(o.offsetFactor, o.offsetUnits);
    }
}

void StyleChain::setDrawnState(const SceneObject& first, GLenum testedFunc)
{
    const GlFunctions& gl = mContext.gl;
    if (first.depthTest) gl.DepthFunc(testedFunc);
    else if (first.depthAlways) gl.DepthFunc(GL_ALWAYS);
    else gl.Disable(GL_DEPTH_TEST);
    gl.DepthMask(first.depthWrite ? GL_TRUE : GL_FALSE);
    if (first.translucent) {
        gl.Enable(GL_BLEND);
        gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    }
}

void StyleChain::renderAsDrawn(const Scene& part)
{
    // Translucent text and sprites are drawn over the scene without the depth test.
    forEachRun(part, [&](const Scene& run, const SceneObject& first) {
        setDrawnState(first, GL_LEQUAL);
        mStyles.front()->render(run, mContext);
        mContext.gl.Disable(GL_BLEND);
    });
}

bool StyleChain::renderPlain(const Scene& scene)
{
    const GlFunctions& gl = mContext.gl;
    if (mPlainState == PlainState::Unbuilt) {
        std::string error;
        mPlainState = mPlain.init(gl, error) ? PlainState::Ready : PlainState::Failed;
        if (mPlainState == PlainState::Failed) {
            NPRGL_ERROR("the unstyled pass for scenes read back does not build (%s); they are "
                        "styled",
                        error.c_str());
        }
    }
    if (mPlainState != PlainState::Ready) return false;
    mRun.takeFrameOf(scene);
    forEachRun(scene, [&](const Scene& run, const SceneObject& first) {
        setDrawnState(first, first.depthFunc);
        if (first.depthOnly) gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        mPlain.render(run, mContext);
        gl.Disable(GL_BLEND);
        mContext.colourMaskOn();
    });
    mContext.meshes.endFlush(gl);
    return true;
}

void StyleChain::shutdown()
{
    for (const std::unique_ptr<Style>& style : mStyles) style->shutdown(mContext);
    mStyles.clear();
    mBackgrounds.clear();
    if (mGlowInkReady) mGlowInk.shutdown(mContext.gl);
    mGlowInkReady = false;
    if (mPlainState == PlainState::Ready) mPlain.shutdown(mContext.gl);
    mPlainState = PlainState::Unbuilt;
    if (mContext.gl.DeleteVertexArrays) {
        mContext.meshes.destroy(mContext.gl);
        mContext.gl.DeleteVertexArrays(1, &mContext.vao);
    }
    mContext.vao = 0;
    if (mContext.blankTexture && mContext.gl.DeleteTextures) {
        mContext.gl.DeleteTextures(1, &mContext.blankTexture);
    }
    mContext.blankTexture = 0;
    mAbstractions.destroy(mContext.gl);
}

} // namespace nprgl::styles
