#include "styles/outlines/PencilStyle.h"

#include "common/Log.h"
#include "styles/StyleRegistry.h"
#include "styles/background/PaperGrain.h"
#include "styles/strokes/StrokeTexture.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace nprgl::styles {

namespace {

constexpr const char* kStyle = "pencil";

// Parameters arrive as constants (see fragmentSource()).
const char* kFragment = R"(
uniform vec3 lightDir;
uniform sampler2D grainTex; // grey, 1 = the sheet's surface, darker = its pits
uniform vec2 anchor;        // the object's origin on screen: its hatching moves with it
in vec3 eyeNormal;
in vec4 baseColor;
in vec2 uv;
out vec4 fragColor;
#if CUT
uniform sampler2D detail; // the program's texture (unit 0): its alpha cuts the drawing out
#endif

float lineHash(float k) { return fract(sin(k * 12.9898 + 78.233) * 43758.5453); }

// The ink of one layer of hatching at pixel p: lines `spacing` apart at `angle`, each cut
// into strokes 30-70 pixels long with tapered ends, its own pressure and a slow wobble, all
// fixed by the line's and the stroke's index. t (0..1) is the layer's share of the tone:
// it fades the layer in and widens its lines.
float hatchLayer(vec2 p, float angle, float layer, float t)
{
    if (t <= 0.0) return 0.0;
    vec2 dir = vec2(cos(angle), sin(angle));
    float along = dot(p, dir);
    float across = dot(p, vec2(-dir.y, dir.x)) / spacing;
    float h = lineHash(floor(across) + 31.0 * layer);
    across += 0.08 * sin(along / (40.0 + 30.0 * h) + 6.2832 * h);
    float k = floor(across);
    h = lineHash(k + 31.0 * layer);
    float d = abs(fract(across) - 0.5) * spacing;
    float halfWidth = 0.5 * lineWidth * (0.5 + 1.5 * t);
    float ink = 1.0 - smoothstep(halfWidth - 0.5, halfWidth + 0.5, d);
    float s = (along + 97.0 * h) / (30.0 + 40.0 * h);
    float f = fract(s);
    float taper = smoothstep(0.0, 0.12, f) * smoothstep(1.0, 0.88, f);
    float weight = 0.7 + 0.3 * lineHash(floor(s) + 7.0 * k + 13.0 * layer);
    return ink * taper * weight * pressure * min(3.0 * t, 1.0);
}

void main()
{
    vec3 n = shadingNormal(eyeNormal);
    // The program's light: its lightmap's, its GL lights' or the head-light's.
    float d = litDot(n, lightDir);
    float lightTone = clamp((light - d) / (light - dark), 0.0, 1.0);
#if CUT
    // A cut-out's or decal's texture is its drawing (a painted arrow, a leaf): its darker
    // parts darken the tone as a darker colour does.
    vec4 texel = texture(detail, uv);
    float luminance = dot(baseColor.rgb * texel.rgb, vec3(0.299, 0.587, 0.114));
#else
    float luminance = dot(baseColor.rgb, vec3(0.299, 0.587, 0.114));
#endif
    float tone = 1.0 - (1.0 - lightTone) * (1.0 - colourTone * (1.0 - luminance));
    vec2 p = gl_FragCoord.xy - anchor;
    float keep = 1.0;
    for (int i = 0; i < LAYERS; ++i) {
        float t = clamp(tone * float(LAYERS) - float(i), 0.0, 1.0);
        keep *= 1.0 - hatchLayer(p, angles[i], float(i), t);
    }
    // No mipmaps: the grain is drawn at its own size.
    float g = textureLod(grainTex, gl_FragCoord.xy / grainSize, 0.0).r;
    // Graphite skips the sheet's pits; the paper keeps its grain.
    float ink = (1.0 - keep) * mix(0.55, 1.0, g);
    vec3 sheet = paper * (1.0 - grain * (1.0 - g));
#if CUT
    // The program's alpha, its texture modulating: what its alpha test and blending see.
    fragColor = vec4(mix(sheet, graphite, ink), baseColor.a * texel.a);
#else
    fragColor = vec4(mix(sheet, graphite, ink), 1.0);
#endif
}
)";

std::unique_ptr<Style> create() { return std::make_unique<PencilStyle>(); }

} // namespace

StyleInfo pencilStyleInfo()
{
    StyleInfo info;
    info.name = kStyle;
    info.summary = "pencil drawing (HijackGL): hatching on paper by L.n, outlines as "
                   "overdrawn tapered pencil strokes; draws on paper";
    info.role = StyleRole::Outline;
    info.lightPage = true;
    info.background = "paper";
    info.create = &create;
    auto& p = info.params;
    p.push_back(ParamInfo::colour("graphite", "colour of the graphite, hex rrggbb", "34373d"));
    p.push_back(ParamInfo::flag("fill", "hatching on paper over the surfaces (off: only the "
                                        "strokes, over the program's or the shading's picture)",
                                true));
    p.push_back(ParamInfo::number("layers", "hatching layers, each at its own angle, laid "
                                            "down as the tone darkens",
                                  3, 1, 3));
    p.push_back(ParamInfo::number("spacing", "pixels between hatching lines", 5.0, 2.0, 40.0));
    p.push_back(ParamInfo::number("line_width", "width of a hatching line in pixels at mid "
                                                "tone",
                                  1.0, 0.3, 6.0));
    p.push_back(ParamInfo::number("angle", "direction of the first hatching layer, degrees",
                                  50.0, -90.0, 90.0));
    p.push_back(ParamInfo::number("light", "L.n at or above it: bare paper", 0.65, -1.0, 1.0));
    p.push_back(ParamInfo::number("dark", "L.n at or below it: every layer at full weight",
                                  -0.2, -1.0, 1.0)
                    .keptBelow("light", 0.05));
    p.push_back(ParamInfo::number("color_tone", "how much a darker program colour darkens "
                                                "the tone",
                                  0.5, 0.0, 1.0));
    p.push_back(ParamInfo::number("pressure", "darkness of the hatching lines", 0.85, 0.0, 1.0));
    p.push_back(ParamInfo::flag("outlines", "overdrawn pencil strokes along silhouettes, "
                                            "creases and borders",
                                true));
    p.push_back(ParamInfo::number("stroke_width", "outline width in pixels (thinner where lit, "
                                                  "thicker in shadow)",
                                  1.8, 0.25, 8.0));
    p.push_back(ParamInfo::number("stroke_passes", "times each outline stroke is drawn", 3, 1,
                                  8));
    p.push_back(ParamInfo::number("stroke_jitter", "wobble of the overdrawn passes, pixels",
                                  1.2, 0.0, 8.0));
    p.push_back(ParamInfo::number("stroke_length", "longest stroke in pixels: longer outlines "
                                                   "are drawn as several strokes (0: no limit)",
                                  120, 0, 100000));
    p.push_back(ParamInfo::number("seed", "seed of the precomputed per-vertex jitter", 1, 0,
                                  1e6));
    return info;
}

std::string PencilStyle::fragmentSource(bool cut, int lights) const
{
    auto f = [](float v) { return ShadingCommon::glslFloat(v); };
    const float a = glm::radians(mAngle);
    std::string s = "#version 130\n";
    s += cut ? "#define CUT 1\n" : "#define CUT 0\n";
    s += "#define LAYERS " + std::to_string(mLayers) + "\n";
    // The second layer crosses the first; the third runs between them.
    s += "const float angles[3] = float[3](" + f(a) + ", " + f(a - 1.5707964f) + ", " +
         f(a - 0.7853982f) + ");\n";
    s += "const float spacing = " + f(mSpacing) + ";\n";
    s += "const float lineWidth = " + f(mLineWidth) + ";\n";
    s += "const float light = " + f(mLight) + ";\n";
    s += "const float dark = " + f(mDark) + ";\n";
    s += "const float colourTone = " + f(mColourTone) + ";\n";
    s += "const float pressure = " + f(mPressure) + ";\n";
    s += "const float grain = " + f(mGrain) + ";\n";
    s += "const float grainSize = " + f(float(std::max(mGrainImage.width, 1))) + ";\n";
    s += "const vec3 paper = " + ShadingCommon::glslVec3(mPaper) + ";\n";
    s += "const vec3 graphite = " + ShadingCommon::glslVec3(mGraphite) + ";\n";
    return s + ShadingCommon::normalFunction(lights) + kFragment;
}

bool PencilStyle::buildVariant(const GlFunctions& gl, int k, std::string& error)
{
    const std::string fragment = fragmentSource(k % 2 == 1, ShadingCommon::variantLights(k));
    Variant& v = mVariants[k];
    if (!ShadingCommon::buildProgram(gl, v.program, v.u, fragment, error)) return false;
    v.anchor = v.program.uniform(gl, "anchor");
    v.grainTex = v.program.uniform(gl, "grainTex");
    return true;
}

bool PencilStyle::init(StyleContext& ctx, std::string& error)
{
    const GlFunctions& gl = ctx.gl;
    auto param = [&](const char* name) { return float(ctx.param(kStyle, name)); };
    mGraphite = ctx.colour(kStyle, "graphite", "34373d");
    // The sheet under the hatching is the page's: paper's colour and grain.
    mPaper = ctx.colour("paper", "color", "f4efe1");
    mGrain = float(ctx.param("paper", "grain"));
    mFill = param("fill") >= 0.5f;
    mOutlines = param("outlines") >= 0.5f;
    mLayers = std::clamp(int(std::lround(param("layers"))), 1, 3);
    mSpacing = param("spacing");
    mLineWidth = param("line_width");
    mAngle = param("angle");
    mLight = param("light");
    mDark = param("dark");
    if (mDark > mLight - 0.05f + 1e-5f) { // a dark given exactly 0.05 below is kept
        NPRGL_WARN("pencil: dark (%.2f) must lie below light (%.2f); using dark = light - 0.05",
                   double(mDark), double(mLight));
        mDark = mLight - 0.05f;
    }
    mColourTone = param("color_tone");
    mPressure = param("pressure");
    mGrainImage = PaperGrain::make(PaperGrain::Options{});
    // Unlit objects' variants now; those for lit ones when first needed (variantFor).
    for (int k = 0; mFill && k < 2; ++k) {
        if (!buildVariant(gl, k, error)) return false;
    }
    if (mOutlines && !mStrokes.init(gl, error)) return false;

    // The outlines: textured pencil strokes, overdrawn with a fixed per-vertex wobble.
    strokes::StrokeRenderer::Options& o = mStrokeOptions;
    o.visibility = strokes::StrokeRenderer::Visibility::Depth;
    o.extract.creases = true;
    o.extract.borders = true;
    o.build.maxAngle = 60.0f;
    o.build.minLength = 4.0f;
    o.build.maxLength = param("stroke_length");
    o.paint.widthMode = strokes::StrokePainter::WidthMode::Light;
    const float width = param("stroke_width");
    o.paint.width = width;
    o.paint.minWidth = 0.6f * width;
    o.paint.maxWidth = 1.4f * width;
    o.paint.passes = uint32_t(std::lround(param("stroke_passes")));
    o.paint.jitter = param("stroke_jitter");
    o.paint.seed = uint32_t(param("seed"));
    // The passes together reach about 0.97 where they overlap: the grain of the pencil
    // texture still lets the paper through.
    o.paint.opacity = 1.0f - std::pow(0.03f, 1.0f / float(std::max(o.paint.passes, 1u)));
    o.draw.textured = true;
    o.draw.color = glm::vec4(mGraphite, 1.0f);
    o.draw.capLength = 14.0f;
    o.draw.tileLength = 96.0f;
    strokes::StrokeTexture::generate(strokes::StrokeTexture::Kind::Pencil, mStrokeTexture);
    mTextureSent = false;
    return true;
}

void PencilStyle::drawSurfaces(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    if (!mGrainTexture.valid()) {
        gl.ActiveTexture(GL_TEXTURE1);
        mGrainTexture.upload(gl, mGrainImage, false);
        gl.ActiveTexture(GL_TEXTURE0);
    }
    gl.ActiveTexture(GL_TEXTURE1);
    gl.BindTexture(GL_TEXTURE_2D, mGrainTexture.id());
    gl.ActiveTexture(GL_TEXTURE0);
    // Onto the surfaces' own depth (the baseline's LEQUAL and offset); the depth stays the
    // scene's for the strokes' visibility.
    gl.DepthMask(GL_FALSE);
    GLuint bound = 0;
    for (const SceneObject& listed : scene.objects) {
        const SceneObject& object = ShadingCommon::withGenerated(listed, false, mReflected);
        if (!object.mesh) continue;
        // Cut-outs and translucent surfaces are drawn where the program's texture and alpha
        // test let them be, blended by its alpha: a tree's quad is hatched as the tree.
        const bool cut = object.alphaFunc != GL_ALWAYS || object.translucent;
        const Variant& v = ShadingCommon::variantFor(
            mVariants, mVariantsFailed, cut, object,
            [&](int k, std::string& error) { return buildVariant(gl, k, error); });
        if (bound != v.program.id()) {
            gl.UseProgram(v.program.id());
            gl.Uniform1i(v.grainTex, 1);
            bound = v.program.id();
        }
        if (object.alphaFunc != GL_ALWAYS) {
            gl.Enable(GL_ALPHA_TEST);
            gl.AlphaFunc(object.alphaFunc, object.alphaRef);
        }
        if (object.translucent) {
            gl.Enable(GL_BLEND);
            gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
        }
        v.u.set(gl, object);
        const glm::vec2 anchor = ShadingCommon::screenAnchor(object, scene.viewport);
        gl.Uniform2f(v.anchor, anchor.x, anchor.y);
        // The program's culling, and its lightmaps bound where it has them.
        ShadingCommon::draw(ctx, object, v.u, cut);
        gl.Disable(GL_ALPHA_TEST);
        gl.Disable(GL_BLEND);
    }
    gl.DepthMask(GL_TRUE);
    gl.ActiveTexture(GL_TEXTURE1);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.ActiveTexture(GL_TEXTURE0);
}

void PencilStyle::render(const Scene& scene, StyleContext& ctx)
{
    if (scene.objects.empty() || scene.viewport.z <= 0 || scene.viewport.w <= 0) return;
    if (mFill) drawSurfaces(scene, ctx);
    if (!mOutlines) return;
    if (!mTextureSent) {
        mStrokes.setTexture(ctx.gl, mStrokeTexture);
        mTextureSent = true;
    }
    ctx.gl.UseProgram(0);
    // A cut-out's or translucent surface's polygons are not its shape (a tree's quad):
    // strokes follow the solid objects only.
    auto solid = [](const SceneObject& o) { return o.alphaFunc == GL_ALWAYS && !o.translucent; };
    if (std::all_of(scene.objects.begin(), scene.objects.end(), solid)) {
        mStrokes.render(scene, ctx.gl, mStrokeOptions);
        return;
    }
    mSolid.objects.clear();
    std::copy_if(scene.objects.begin(), scene.objects.end(), std::back_inserter(mSolid.objects),
                 solid);
    if (mSolid.objects.empty()) return;
    mSolid.takeFrameOf(scene);
    mStrokes.render(mSolid, ctx.gl, mStrokeOptions);
}

void PencilStyle::shutdown(StyleContext& ctx)
{
    for (Variant& v : mVariants) v.program.destroy(ctx.gl);
    mGrainTexture.destroy(ctx.gl);
    mStrokes.destroy(ctx.gl);
    mTextureSent = false;
}

} // namespace nprgl::styles
