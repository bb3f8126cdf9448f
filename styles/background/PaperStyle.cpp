#include "styles/background/PaperStyle.h"

#include "common/Log.h"
#include "styles/ObjectNames.h"
#include "styles/StyleRegistry.h"
#include "styles/background/PaperGrain.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace nprgl::styles {

namespace {

const char* kStyle = "paper";
const char* kDefaultColour = "f4efe1";
const char* kDefaultDarkColour = "15171a"; // a slate: the page of a program drawn on black

// The triangle covers the viewport at the far plane: with depth test GL_LEQUAL the fill pass
// reaches only pixels whose depth is still the cleared far value (the depth test rejects
// the scene before any shading, which is what makes the pass cheap on a software rasteriser).
const char* kVertex = R"(#version 130
in vec3 position;
void main() { gl_Position = vec4(position.xy, 1.0, 1.0); }
)";

// Pass 0 (grain_scene) grains the whole viewport: multiplied (blend DST_COLOR, ZERO).
// Pass 1 lays the page where nothing drew depth and the colour (copied before the flush) is
// still the clear colour (a 2D backdrop drawn without depth keeps its pixels) or, when nothing
// was drawn since the clear (Scene::colourFresh), wherever nothing drew depth: the grained
// paper, opaque (a page has no holes, even where the program cleared alpha to 0), blended
// in by an alpha of 1 there and 0 elsewhere.
const char* kFragment = R"(#version 130
uniform sampler2D colour;    // copy of the viewport's colour before the grain
uniform sampler2D grainTex;  // grey, 1 = untouched
uniform sampler2D paperTex;  // the user's paper scan
uniform int pass;
uniform ivec2 origin;
uniform bool usePaperTex;
uniform bool compare;        // false: nothing was drawn since the clear, every pixel is page
uniform vec3 paperColour;
uniform vec3 clearColour;
uniform float tolerance;
uniform float grain;
uniform vec2 grainSize;      // one grain tile on screen, pixels
uniform vec2 paperSize;      // one paper tile on screen, pixels
out vec4 fragColor;

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy) - origin;
    vec2 q = vec2(p) + 0.5;
    // No mipmaps: the grain is drawn at (about) its own size, level 0 is the right one.
    float factor = 1.0 - grain * (1.0 - textureLod(grainTex, q / grainSize, 0.0).r);
    if (pass == 0) {
        fragColor = vec4(vec3(factor), 1.0);
        return;
    }
    // No discard (it would turn off the early depth test that skips the scene's pixels):
    // alpha 0 leaves the pixel as it is through the blend.
    float untouched = 1.0;
    if (compare) {
        vec3 d = abs(texelFetch(colour, p, 0).rgb - clearColour);
        untouched = max(d.r, max(d.g, d.b)) > tolerance ? 0.0 : 1.0;
    }
    vec3 paper = paperColour;
    if (usePaperTex) {
        // Upright: the image's top row was uploaded first (t = 0).
        vec4 t = texture(paperTex, vec2(q.x, -q.y) / paperSize);
        paper = mix(paperColour, t.rgb, t.a);
    }
    fragColor = vec4(paper * factor, untouched);
}
)";

std::unique_ptr<Style> create() { return std::make_unique<PaperStyle>(); }

} // namespace

StyleInfo paperStyleInfo()
{
    StyleInfo info;
    info.name = kStyle;
    info.summary = "the page: the program's cleared background becomes paper and a fine paper "
                   "grain lies over the picture (thesis 2.4.2, appendix B)";
    info.role = StyleRole::Background;
    info.create = &create;
    info.params = {
        ParamInfo::colour("color", "paper colour, hex rrggbb (a light page)", kDefaultColour),
        ParamInfo::choice("tone",
                          "the page's tone: auto follows the program's background (a dark "
                          "page with light ink where it clears to a dark colour), or always "
                          "light or dark",
                          {"auto", "light", "dark"}, 0),
        ParamInfo::colour("dark_color", "paper colour of a dark page, hex rrggbb",
                          kDefaultDarkColour),
        ParamInfo::flag("background",
                        "replace the program's untouched background (far depth, clear "
                        "colour) with paper (on/off)",
                        true),
        ParamInfo::number("grain", "strength of the paper grain multiplied over the viewport",
                          0.12, 0.0, 1.0),
        ParamInfo::flag("grain_scene",
                        "the grain over the scene too, not only the paper (a full-screen "
                        "pass: on a software rasteriser it costs about a frame of a small "
                        "program)",
                        false),
        ParamInfo::number("grain_scale", "size of the grain (and of texture_png's tiles)", 1.0,
                          0.25, 8.0),
        ParamInfo::text("texture_png", "a paper scan tiled over the background instead of the "
                                       "flat colour (empty: none)"),
    };
    return info;
}

bool PaperStyle::colourConfigured(const StyleContext& ctx, glm::vec3& colour)
{
    glm::vec3 fallback(1.0f);
    ParamInfo::parseColour(kDefaultColour, fallback);
    return ParamInfo::parseColour(ctx.text(kStyle, "color"), colour) && colour != fallback;
}

bool PaperStyle::init(StyleContext& ctx, std::string& error)
{
    const GlFunctions& gl = ctx.gl;
    if (!mProgram.build(gl, kVertex, kFragment, error)) return false;
    auto at = [&](const char* name) { return mProgram.uniform(gl, name); };
    mU = {at("colour"),      at("grainTex"),    at("paperTex"),    at("origin"),
          at("usePaperTex"), at("paperColour"), at("clearColour"), at("tolerance"),
          at("grain"),       at("pass"),        at("grainSize"),   at("paperSize"),
          at("compare")};

    mPaperColour = ctx.colour(kStyle, "color", kDefaultColour);
    mDarkColour = ctx.colour(kStyle, "dark_color", kDefaultDarkColour);
    glm::vec3 chosen(1.0f);
    mColourChosen = colourConfigured(ctx, chosen);
    mFill = ctx.param(kStyle, "background") >= 0.5;
    mGrain = float(std::clamp(ctx.param(kStyle, "grain"), 0.0, 1.0));
    mGrainScene = ctx.param(kStyle, "grain_scene") >= 0.5;
    mGrainScale = float(std::clamp(ctx.param(kStyle, "grain_scale"), 0.25, 8.0));
    if (mGrain > 0.0f) mGrainImage = PaperGrain::make(PaperGrain::Options{});

    const std::string png = ctx.text(kStyle, "texture_png");
    if (!png.empty()) {
        std::string why;
        if (!GlTexture::loadPng(png, false, mPaperImage, why)) {
            NPRGL_ERROR("paper: cannot use texture_png '%s' (%s); drawing the procedural "
                        "paper instead",
                        png.c_str(), why.c_str());
            mPaperImage = TextureImage{};
        }
    }

    const float triangle[] = {-1.0f, -1.0f, 0.0f, 3.0f, -1.0f, 0.0f, -1.0f, 3.0f, 0.0f};
    ObjectNames::reserve(gl, ObjectNames::Kind::Buffer, 1, &mTriangle);
    gl.BindBuffer(GL_ARRAY_BUFFER, mTriangle);
    gl.BufferData(GL_ARRAY_BUFFER, sizeof(triangle), triangle, GL_STATIC_DRAW);
    gl.BindBuffer(GL_ARRAY_BUFFER, 0);
    return true;
}

bool PaperStyle::grainedThisFrame(const Scene& scene, bool mark)
{
    if (scene.frame != mGrainFrame) {
        mGrainFrame = scene.frame;
        mGrainedViewports.clear();
    }
    if (std::find(mGrainedViewports.begin(), mGrainedViewports.end(), scene.viewport) !=
        mGrainedViewports.end()) {
        return true;
    }
    if (mark) mGrainedViewports.push_back(scene.viewport);
    return false;
}

bool PaperStyle::filledAlready(const Scene& scene, bool mark)
{
    // A flush after the page was laid adds objects that wrote depth over it; the pixels
    // still untouched are paper already. A colour clear since makes new background.
    if (scene.frame != mFillFrame) {
        mFillFrame = scene.frame;
        mFilled.clear();
    }
    const Filled key{scene.framebuffer, scene.viewport, scene.colourClears};
    if (std::find(mFilled.begin(), mFilled.end(), key) != mFilled.end()) return true;
    if (mark) mFilled.push_back(key);
    return false;
}

void PaperStyle::beginPass(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    const glm::ivec4 vp = scene.viewport;
    // Textures are uploaded here, where the program's state is saved (GlTexture::upload).
    if (!mGrainImage.empty() && !mGrainTexture.valid()) {
        mGrainTexture.upload(gl, mGrainImage, false);
    }
    if (!mPaperImage.empty() && !mPaperTexture.valid()) mPaperTexture.upload(gl, mPaperImage);

    gl.UseProgram(mProgram.id());
    gl.Uniform1i(mU.colour, 0);
    gl.Uniform1i(mU.grainTex, 2);
    gl.Uniform1i(mU.paperTex, 3);
    gl.Uniform2i(mU.origin, vp.x, vp.y);
    gl.Uniform1i(mU.usePaperTex, mPaperTexture.valid() ? 1 : 0);
    const glm::vec3 paper = ctx.page.dark() && !mColourChosen ? mDarkColour : mPaperColour;
    gl.Uniform3f(mU.paperColour, paper.r, paper.g, paper.b);
    const glm::vec3 clear = glm::clamp(glm::vec3(scene.clearColor), 0.0f, 1.0f);
    gl.Uniform3f(mU.clearColour, clear.r, clear.g, clear.b);
    // One and a half steps of the coarser of the framebuffer and the 8-bit copy.
    const int bits = std::clamp(mCopy.colourBits(), 1, 8);
    gl.Uniform1f(mU.tolerance, 1.5f / float((1 << bits) - 1));
    gl.Uniform1f(mU.grain, mGrainTexture.valid() ? mGrain : 0.0f);
    const float grainTile = float(std::max(mGrainImage.width, 1)) * mGrainScale;
    gl.Uniform2f(mU.grainSize, grainTile, grainTile);
    gl.Uniform2f(mU.paperSize, float(std::max(mPaperImage.width, 1)) * mGrainScale,
                 float(std::max(mPaperImage.height, 1)) * mGrainScale);

    const GLuint textures[4] = {mCopy.colour(), 0, mGrainTexture.id(), mPaperTexture.id()};
    for (int i = 3; i >= 0; --i) {
        gl.ActiveTexture(GL_TEXTURE0 + GLenum(i));
        gl.BindTexture(GL_TEXTURE_2D, textures[i]);
    }

    // Only the viewport; the scene's depth stays for the outline styles.
    ctx.scissorTo(scene, vp);
    gl.DepthMask(GL_FALSE);
    gl.BindBuffer(GL_ARRAY_BUFFER, mTriangle);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    gl.EnableVertexAttribArray(0);
    for (GLuint a = 1; a < 4; ++a) gl.DisableVertexAttribArray(a);
}

void PaperStyle::endPass(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    gl.DisableVertexAttribArray(0);
    gl.BindBuffer(GL_ARRAY_BUFFER, 0);
    for (int i = 3; i >= 0; --i) {
        gl.ActiveTexture(GL_TEXTURE0 + GLenum(i));
        gl.BindTexture(GL_TEXTURE_2D, 0);
    }
    // Back to the baseline masks: a clear that follows (before anyone restores the state)
    // must reach the whole depth and colour buffers.
    gl.Disable(GL_BLEND);
    ctx.endScissor(scene);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthMask(GL_TRUE);
    ctx.colourMaskOn();
}

bool PaperStyle::copyBackground(const Scene& scene, StyleContext& ctx)
{
    if (mCopy.capture(ctx.gl, scene.viewport)) return true;
    if (!mWarnedCopy) {
        NPRGL_WARN("paper: cannot copy a multisampled (or undrawn) framebuffer; the "
                   "background is left as the program cleared it");
    }
    mWarnedCopy = true;
    return false;
}

void PaperStyle::keepBackground(const Scene& scene, StyleContext& ctx)
{
    mKept = false;
    const glm::ivec4 vp = scene.viewport;
    // A fresh buffer needs no copy: nothing in it is the program's but the clear.
    if (!mFill || scene.objects.empty() || vp.z <= 0 || vp.w <= 0 || scene.colourFresh ||
        scene.copiedToTexture || filledAlready(scene, false)) {
        return;
    }
    mKept = copyBackground(scene, ctx);
    mKeptFrame = scene.frame;
    mKeptViewport = vp;
}

void PaperStyle::layBackground(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    const glm::ivec4 vp = scene.viewport;
    const bool kept = std::exchange(mKept, false);
    // An empty flush drew nothing; its page is whatever the program left. Pixels the program
    // copies into a texture (a ball's environment map: foobillardplus's balls reflect it,
    // added by GL_ONE_MINUS_DST_COLOR) keep its background: paper there is paper in the
    // reflection, and washed its balls white.
    if (!mFill || scene.objects.empty() || vp.z <= 0 || vp.w <= 0 || scene.copiedToTexture ||
        filledAlready(scene, true)) {
        return;
    }
    // The copy of what was there before the flush drew (the same viewport and frame).
    const bool copied = kept && mKeptFrame == scene.frame && mKeptViewport == vp;
    if (!scene.colourFresh && !copied && !copyBackground(scene, ctx)) return;
    beginPass(scene, ctx);
    gl.Uniform1i(mU.compare, scene.colourFresh ? 0 : 1);
    // Grained here unless the grain goes over the whole viewport after the scene.
    if (mGrainScene && !grainedThisFrame(scene, false)) gl.Uniform1f(mU.grain, 0.0f);
    gl.Uniform1i(mU.pass, 1);
    ctx.colourMaskOn();
    // Depth still at the far plane: nothing was drawn there (without a depth buffer every
    // pixel passes and the colour alone decides).
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LEQUAL);
    gl.Disable(GL_POLYGON_OFFSET_FILL);
    gl.DepthRange(0.0, 1.0);
    // Paper where untouched (alpha 1, and the page's alpha becomes 1), else unchanged.
    gl.Enable(GL_BLEND);
    gl.BlendEquation(GL_FUNC_ADD);
    gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    endPass(scene, ctx);
}

void PaperStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    const glm::ivec4 vp = scene.viewport;
    if (scene.objects.empty() || vp.z <= 0 || vp.w <= 0 || scene.copiedToTexture) return;
    // Laid already when the chain called layBackground first in this flush.
    layBackground(scene, ctx);
    if (!mGrainScene || mGrain <= 0.0f || grainedThisFrame(scene, true)) return;
    beginPass(scene, ctx);
    // Multiplied into colour only: the program's alpha over its scene stays.
    gl.Disable(GL_DEPTH_TEST);
    gl.Uniform1i(mU.pass, 0);
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    gl.Enable(GL_BLEND);
    gl.BlendEquation(GL_FUNC_ADD);
    gl.BlendFunc(GL_DST_COLOR, GL_ZERO);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
    endPass(scene, ctx);
}

void PaperStyle::shutdown(StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    mProgram.destroy(gl);
    mCopy.destroy(gl);
    mGrainTexture.destroy(gl);
    mPaperTexture.destroy(gl);
    if (mTriangle) gl.DeleteBuffers(1, &mTriangle);
    mTriangle = 0;
}

} // namespace nprgl::styles
