#include "styles/shading/ToonStyle.h"

#include "common/Log.h"
#include "styles/StyleRegistry.h"
#include "styles/shading/ShadingCommon.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace nprgl::styles {

namespace {

// The parameters arrive as #defines and constants (see fragmentSource()).
const char* kFragment = R"(
uniform vec3 lightDir;
uniform sampler2D detail;
in vec3 eyeNormal;
in vec4 baseColor;
in vec2 uv;
out vec4 fragColor;

// The shadow band's share of the base colour: the style's, or the program's own where its
// shadowed side is darker (GL's ambient terms, thesis eq. 3.3), down to the floor.
float shadowShare()
{
    return ambientShare < 0.0 ? shadowScale : clamp(ambientShare, shadowFloor, shadowScale);
}

// The shadow band's colour: GL's own unlit colour (its share of the base, in its hue:
// SceneLights::shadowTint), and what the style adds over it up to shadowShare() in the base's.
vec3 shadowColour(vec3 base)
{
    float share = shadowShare();
    float own = clamp(ambientShare, 0.0, share);
    return min(base * (own * shadowTint + (share - own)), vec3(1.0));
}

// 0 below the threshold, 1 above; with SMOOTH a one-pixel ramp (screen-space antialiasing of
// the band boundary, thesis 3.1.4).
float above(float d, float t, float pixel)
{
#if SMOOTH
    return clamp((d - t) / pixel + 0.5, 0.0, 1.0);
#else
    return d < t ? 0.0 : 1.0;
#endif
}

// Lightness against a colour value: GL's values are sRGB-encoded (a 2.2 power of luminance)
// and L* is about luminance's cube root, so L* goes about as the values' 2.2/3 power.
const float kLightness = 2.2 / 3.0;

// The half band's colour: midway in lightness between the two it parts.
vec3 halfTone(vec3 shadow, vec3 lit)
{
    vec3 k = vec3(kLightness);
    return pow(0.5 * (pow(shadow, k) + pow(lit, k)), 1.0 / k);
}

// Ink coverage of a line lineWidth pixels wide centred on the boundary d == t.
float boundaryInk(float d, float t, float pixel)
{
    float dist = abs(d - t) / pixel;
    return clamp(0.5 * lineWidth - dist + 0.5, 0.0, 1.0);
}

void main()
{
    vec3 base = baseColor.rgb;
#if PROGRAM_BANDS
    // Where the program lit the object, the normal GL lights it by (programNormal), and GL's
    // light not capped at one light head-on: near a light whose attenuation brightens it, and
    // where lights add up, GL shows the lit colour (clamped).
    bool program = ambientShare >= 0.0;
    vec3 n = program ? programNormal(eyeNormal) : shadingNormal(eyeNormal);
    float d = litDot(n, lightDir, program ? 64.0 : 1.0);
#else
    vec3 n = shadingNormal(eyeNormal);
    float d = litDot(n, lightDir);
#endif
    // The quantities the bands cut, their thresholds, and the highlight colour: the thesis's
    // L.n at t_d and t_h, or (PROGRAM_BANDS) where the program lit the object, GL's own light.
    float x = d, xt = diffuseThreshold;
    float xt2 = 1.0; // HALF_BAND: the cut between the half band and the full colour
    float h = d, ht = highlightThreshold;
    vec3 highlight = HIGHLIGHT_COLOR;
    float shines = 1.0;
#if PROGRAM_BANDS
    if (program) {
        // GL's light here as a share of the lit side's (its ambient share up to 1), in the
        // band nearest it in lightness (kLightness): a face GL leaves dark stays dark, so
        // objects keep the lightness order the program gave them. With the half band midway
        // between shadow and full colour, GL's light is within a quarter of their distance of
        // the band it takes (half of it without): two materials GL shows clearly apart no
        // longer trade places. The highlight where GL's own is over half its peak, in GL's
        // colour (thesis eq. 3.5: a_m + d_m + s_m); none where the material does not shine.
        float adds = diffuseShare >= 0.0 ? diffuseShare : 1.0 - ambientShare;
        x = min(ambientShare + adds * max(d, 0.0), 1.0);
        // t_d moves the cuts from there (0: none), so that its slider still shades more or less.
        float low = pow(shadowShare(), kLightness), back = 1.0 / kLightness;
#if HALF_BAND
        xt = pow(0.25 * (3.0 * low + 1.0), back) + 0.5 * diffuseThreshold;
        xt2 = pow(0.25 * (low + 3.0), back) + 0.5 * diffuseThreshold;
#else
        xt = pow(0.5 * (low + 1.0), back) + 0.5 * diffuseThreshold;
#endif
        h = programShine(n);
        ht = 0.5;
        shines = dot(shine.rgb, shine.rgb) > 0.0 ? 1.0 : 0.0;
        highlight = PROGRAM_HIGHLIGHT;
    }
#endif
#if SMOOTH || BAND_LINES
    float pixel = max(fwidth(x), 1e-5);
    float hpixel = max(fwidth(h), 1e-5);
#else
    float pixel = 1.0, hpixel = 1.0;
#endif
    // Shadow up to xt, then the full colour; where the program lit the object and the half
    // band is on, the half band between xt and xt2.
#if HALF_BAND
    vec3 middle = program ? halfTone(SHADOW_COLOR, DIFFUSE_COLOR) : DIFFUSE_COLOR;
    vec3 c = mix(SHADOW_COLOR, middle, above(x, xt, pixel));
    if (program) c = mix(c, DIFFUSE_COLOR, above(x, xt2, pixel));
#else
    vec3 c = mix(SHADOW_COLOR, DIFFUSE_COLOR, above(x, xt, pixel));
#endif
#if TONES == 3
    c = mix(c, highlight, shines * above(h, ht, hpixel));
#endif
    // The program's alpha, texture modulating: what its alpha test and blending see.
    float alpha = baseColor.a;
#if DETAIL == 1
    vec4 t = texture(detail, uv);
    c = c * t.rgb;
    alpha *= t.a;
#elif DETAIL == 2
    vec4 t = texture(detail, uv);
    c = mix(c, t.rgb, t.a);
    alpha *= t.a;
#endif
#if BAND_LINES
    float ink = boundaryInk(x, xt, pixel);
#if HALF_BAND
    if (program) ink = max(ink, boundaryInk(x, xt2, pixel));
#endif
#if TONES == 3
    ink = max(ink, shines * boundaryInk(h, ht, hpixel));
#endif
    c *= 1.0 - ink;
#endif
    fragColor = vec4(programFog(c, eyePosition), alpha);
}
)";

std::unique_ptr<Style> create() { return std::make_unique<ToonStyle>(); }

} // namespace

StyleInfo toonStyleInfo()
{
    StyleInfo info;
    info.name = "toon";
    info.summary = "cartoon shading: shadow, diffuse and highlight bands (thesis 3.1)";
    info.role = StyleRole::Shading;
    info.create = &create;
    info.params = {
        ParamInfo::number("tones", "number of tones: 2 (shadow, diffuse) or 3 (+ highlight)", 3,
                          2, 3),
        ParamInfo::number("diffuse_threshold", "t_d: L.n below it is shadow", 0.0, -1.0, 1.0)
            .keptBelow("highlight_threshold", 0.02),
        ParamInfo::number("highlight_threshold",
                          "t_h: L.n above it is highlight (kept above t_d)", 0.92, -1.0, 1.0),
        ParamInfo::number("shadow_scale",
                          "shadow colour = base colour x this; where the program's own "
                          "shadowed side is darker (little ambient light), its share, down "
                          "to shadow_floor",
                          0.55, 0.0, 1.0),
        ParamInfo::number("shadow_floor",
                          "the darkest shadow colour, as a share of the base colour, that a "
                          "program's dark shadowed side gives",
                          0.3, 0.0, 1.0),
        ParamInfo::number("highlight_mix", "highlight colour = base mixed with white by this",
                          0.55, 0.0, 1.0),
        ParamInfo::colour("shadow_color", "fixed shadow colour, hex rrggbb (empty: derived)"),
        ParamInfo::colour("diffuse_color", "fixed diffuse colour, hex rrggbb (empty: the "
                                         "program's colour)"),
        ParamInfo::colour("highlight_color", "fixed highlight colour, hex rrggbb (empty: derived)"),
        ParamInfo::choice("bands", "where the bands fall on an object the program lit: "
                                   "program (the band nearest in lightness to GL's own light "
                                   "there, the highlight where GL's specular highlight is) or "
                                   "thesis (t_d and t_h on L.n, a highlight on every object)",
                          {"program", "thesis"}, 0),
        ParamInfo::choice("band", "band boundaries: nearest (hard, like a nearest-filtered "
                                  "shading texture) or smooth (antialiased over one pixel)",
                          {"nearest", "smooth"}, 1),
        ParamInfo::choice("detail", "the program's own texture as detail: off, modulate "
                                    "(multiplied with the shading) or decal (a sticker on top)",
                          {"off", "modulate", "decal"}, 1),
        ParamInfo::flag("half_band",
                        "with bands=program, a half-shadow band midway in lightness between "
                        "the shadow and the full colour (objects GL shows apart in lightness "
                        "keep their order)",
                        true),
        ParamInfo::flag("band_lines", "ink lines between the shade bands (thesis fig. 3.8)",
                        false),
        ShadingCommon::reflectionsParam(),
        ParamInfo::number("texture_detail",
                          "how much of the program's texture detail is kept: 0 draws each "
                          "region of a texture in one colour of a small palette of its own, "
                          "1 is the program's texture (the abstraction is made once per "
                          "texture, off the frame)",
                          ToonStyle::kDefaultTextureDetail, 0.0, 1.0),
        ParamInfo::number("band_line_width", "width of the band lines in pixels", 1.5, 0.5, 8.0),
    };
    return info;
}

std::string ToonStyle::fragmentSource(int detail, int lights) const
{
    auto f = [](float v) { return ShadingCommon::glslFloat(v); };
    std::string s = "#version 130\n";
    s += "#define TONES " + std::to_string(mTones) + "\n";
    s += std::string("#define SMOOTH ") + (mSmooth ? "1" : "0") + "\n";
    s += "#define DETAIL " + std::to_string(detail) + "\n";
    s += std::string("#define BAND_LINES ") + (mBandLines ? "1" : "0") + "\n";
    s += std::string("#define PROGRAM_BANDS ") + (mProgramBands && lights > 0 ? "1" : "0") + "\n";
    const bool half = mProgramBands && lights > 0 && mHalfBand;
    s += std::string("#define HALF_BAND ") + (half ? "1" : "0") + "\n";
    s += "const float diffuseThreshold = " + f(mDiffuseThreshold) + ";\n";
    s += "const float highlightThreshold = " + f(mHighlightThreshold) + ";\n";
    s += "const float lineWidth = " + f(mLineWidth) + ";\n";
    s += "const float shadowScale = " + f(mShadowScale) + ";\n";
    s += "const float shadowFloor = " + f(std::min(mShadowFloor, mShadowScale)) + ";\n";
    // The band colours: configured constants, else derived from the program's colour.
    auto colour = [&](const char* name, int i, const std::string& derived) {
        const bool fixed = mFixed & (1 << i);
        return std::string("#define ") + name + " " +
               (fixed ? ShadingCommon::glslVec3(mColors[i]) : derived) + "\n";
    };
    s += colour("SHADOW_COLOR", 0, "shadowColour(base)");
    s += colour("DIFFUSE_COLOR", 1, "base");
    s += colour("HIGHLIGHT_COLOR", 2, "mix(base, vec3(1.0), " + f(mHighlightMix) + ")");
    s += colour("PROGRAM_HIGHLIGHT", 2, "min(base + shine.rgb, vec3(1.0))");
    return s + ShadingCommon::normalFunction(lights) + ShadingCommon::fogFunction() +
           kFragment;
}

bool ToonStyle::buildVariant(const GlFunctions& gl, int k, std::string& error)
{
    const std::string fragment =
        fragmentSource(k % 2 == 0 ? 0 : mDetail, ShadingCommon::variantLights(k));
    Variant& variant = mVariants[k];
    if (!ShadingCommon::buildProgram(gl, variant.program, variant.u, fragment, error)) {
        return false;
    }
    return true;
}

bool ToonStyle::init(StyleContext& ctx, std::string& error)
{
    const GlFunctions& gl = ctx.gl;
    mTones = int(std::lround(ctx.param("toon", "tones"))) <= 2 ? 2 : 3;
    mDiffuseThreshold = float(ctx.param("toon", "diffuse_threshold"));
    mHighlightThreshold = float(ctx.param("toon", "highlight_threshold"));
    // The thesis needs -1 <= t_d < t_h <= 1; with three tones a highlight at or below the
    // diffuse threshold would hide the diffuse band, so keep t_h just above t_d.
    if (mTones == 3 && mDiffuseThreshold >= mHighlightThreshold) {
        const float td = std::min(mDiffuseThreshold, 0.98f);
        const float th = std::min(td + 0.02f, 1.0f);
        NPRGL_WARN("toon: diffuse_threshold (%.3g) must be below highlight_threshold (%.3g); "
                   "using %.3g and %.3g",
                   double(mDiffuseThreshold), double(mHighlightThreshold), double(td),
                   double(th));
        mDiffuseThreshold = td;
        mHighlightThreshold = th;
    }
    mShadowScale = float(ctx.param("toon", "shadow_scale"));
    mShadowFloor = float(ctx.param("toon", "shadow_floor"));
    mHighlightMix = float(ctx.param("toon", "highlight_mix"));
    mProgramBands = ctx.param("toon", "bands") < 0.5;
    mHalfBand = ctx.param("toon", "half_band") >= 0.5;
    mSmooth = ctx.param("toon", "band") >= 0.5;
    mDetail = int(std::lround(ctx.param("toon", "detail")));
    mBandLines = ctx.param("toon", "band_lines") >= 0.5;
    mReflections = ctx.param("toon", "reflections") >= 0.5;
    mLineWidth = float(ctx.param("toon", "band_line_width"));
    mTextureDetail = float(ctx.param("toon", "texture_detail"));
    const char* colorNames[3] = {"shadow_color", "diffuse_color", "highlight_color"};
    for (int i = 0; i < 3; ++i) {
        const std::string text = ctx.text("toon", colorNames[i]);
        const bool fixed = ParamInfo::parseColour(text, mColors[i]);
        if (fixed) mFixed |= 1 << i;
        if (!text.empty() && !fixed) {
            NPRGL_ERROR("toon: %s='%s' is not a hex colour rrggbb; using the derived colour",
                        colorNames[i], text.c_str());
        }
    }
    // Untextured objects, and the detail mode for textured ones (when it is on).
    // Unlit objects' variants now; those for lit ones when first needed (variantFor).
    for (int k = 0; k < (mDetail != 0 ? 2 : 1); ++k) {
        if (!buildVariant(gl, k, error)) return false;
    }
    return true;
}

void ToonStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    // The detail sampler is unit 0, the default of sampler uniforms.
    GLuint current = 0;
    ctx.textureDetail = mTextureDetail;
    for (const SceneObject& listed : scene.objects) {
        const SceneObject& object = ShadingCommon::withGenerated(listed, mReflections, mReflected);
        const bool textured = object.textured() && mDetail != 0;
        Variant& variant = ShadingCommon::variantFor(
            mVariants, mVariantsFailed, textured, object,
            [&](int k, std::string& error) { return buildVariant(gl, k, error); });
        if (variant.program.id() != current) {
            current = variant.program.id();
            gl.UseProgram(current);
        }
        variant.u.set(gl, object);
        // The program's textures keep their own filtering and wrapping; both sides are
        // drawn in one pass (shadingNormal).
        ShadingCommon::draw(ctx, object, variant.u, textured);
    }
    ctx.textureDetail = 1.0f;
}

void ToonStyle::shutdown(StyleContext& ctx)
{
    for (Variant& variant : mVariants) variant.program.destroy(ctx.gl);
}

} // namespace nprgl::styles
