#include "styles/shading/TexturedStyle.h"

#include "common/Log.h"
#include "styles/StyleRegistry.h"
#include "styles/shading/ShadingCommon.h"
#include "styles/textures/HatchTexture.h"
#include "styles/textures/StippleTexture.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace nprgl::styles {

namespace {

// The parameters arrive as #defines and constants, the layers as lightLayer() and
// shadowLayer() (see fragmentSource()).
const char* kFragment = R"(
float ramp(float x, float lo, float hi)
{
    return clamp((x - lo) / max(hi - lo, 1e-4), 0.0, 1.0);
}

void main()
{
    vec3 n = shadingNormal(eyeNormal);
    float d = litDot(n, lightDir);
    float pixel = max(fwidth(d), 1e-5);
    // The shading colours (the 1D shading texture's colour channels), antialiased bands.
#if TINT
    vec3 base = baseColor.rgb;
#else
    vec3 base = vec3(1.0);
#endif
    float lit = clamp((d - diffuseThreshold) / pixel + 0.5, 0.0, 1.0);
    vec3 shade = mix(base * shadowScale, base, lit);
#if TONES == 3
    vec3 ch = mix(base, vec3(1.0), highlightMix);
    shade = mix(shade, ch, clamp((d - highlightThreshold) / pixel + 0.5, 0.0, 1.0));
#endif
    vec3 L = lightLayer();
    vec3 S = shadowLayer();
#if !ASYMMETRIC
    // The thesis's two passes: shadow layer, then the light layer blended over it by the
    // shading texture's alpha ramp.
    vec3 c = shade * mix(S, L, ramp(d, bandLow, bandHigh));
#else
    // Both layers overlap inside the band; each falls off steeply at its own end.
    float w = (bandHigh - bandLow) * falloff;
    float wl = ramp(d, bandLow, bandLow + w);
    float ws = 1.0 - ramp(d, bandHigh - w, bandHigh);
    vec3 c = shade * mix(vec3(1.0), L, wl) * mix(vec3(1.0), S, ws);
#endif
#if PROGRAM_TEXTURE
    // The program's alpha, its texture modulating: what its alpha test and blending see.
    fragColor = vec4(programFog(c, eyePosition), baseColor.a * texture(programTex, uv).a);
#else
    fragColor = vec4(programFog(c, eyePosition), baseColor.a);
#endif
}
)";

const std::vector<std::string> kSources = {"none",    "paper",  "hatching", "crosshatching",
                                           "stipple", "program"};

std::unique_ptr<Style> create() { return std::make_unique<TexturedStyle>(); }

TextureImage procedural(TexturedStyle::Source source)
{
    switch (source) {
    case TexturedStyle::Hatching: {
        HatchTexture::Options o;
        o.spacing = 8;
        o.width = 1.2f;
        return HatchTexture::make(o);
    }
    case TexturedStyle::CrossHatching: {
        HatchTexture::Options o;
        o.size = 96; // a multiple of the spacing, so the tile repeats seamlessly
        o.spacing = 6;
        o.width = 1.3f;
        o.cross = true;
        o.seed = 2;
        return HatchTexture::make(o);
    }
    case TexturedStyle::Stipple: return StippleTexture::make({});
    default: return {};
    }
}

// Layer modes of the shader.
int modeOf(TexturedStyle::Source source, const TextureImage& image, bool programTexture)
{
    if (source == TexturedStyle::Program) return programTexture ? 2 : 0;
    if (image.empty()) return 0;
    return image.channels == 1 ? 1 : 3;
}

} // namespace

StyleInfo texturedStyleInfo()
{
    StyleInfo info;
    info.name = "textured";
    info.summary = "textured shading: a light texture on lit and a shadow texture on shadowed "
                   "regions (thesis 3.2)";
    info.role = StyleRole::Shading;
    info.create = &create;
    info.params = {
        ParamInfo::number("tones", "shading colours: 2 (shadow, diffuse) or 3 (+ highlight)", 2,
                          2, 3),
        ParamInfo::number("diffuse_threshold", "t_d: L.n below it takes the shadow colour", 0.0,
                          -1.0, 1.0)
            .keptBelow("highlight_threshold", 0.02),
        ParamInfo::number("highlight_threshold", "t_h: L.n above it takes the highlight colour",
                          0.92, -1.0, 1.0),
        ParamInfo::number("shadow_scale", "shadow colour = base colour x this", 0.75, 0.0, 1.0),
        ParamInfo::number("highlight_mix", "highlight colour = base mixed with white by this",
                          0.55, 0.0, 1.0),
        ParamInfo::flag("tint", "shading colours from the program's colour (off: white paper, "
                                "ink only)",
                        true),
        ShadingCommon::reflectionsParam(),
        ParamInfo::number("alpha_low", "ta_l: L.n where the light texture starts to fade in",
                          -0.15, -1.0, 1.0)
            .keptBelow("alpha_high", 0.0),
        ParamInfo::number("alpha_high", "ta_u: L.n where only the light texture remains", 0.15,
                          -1.0, 1.0),
        ParamInfo::choice("transition", "symmetric (one cross-fade) or asymmetric (both "
                                        "textures overlap in the band, steep ends; fig. 3.13)",
                          {"symmetric", "asymmetric"}, 1),
        ParamInfo::number("falloff", "asymmetric: share of the band over which each texture "
                                     "fades",
                          0.3, 0.05, 1.0),
        ParamInfo::choice("light_texture", "texture of the lit region (program: the program's "
                                           "own texture, blank without one)",
                          kSources, 5),
        ParamInfo::choice("shadow_texture", "texture of the shadowed region", kSources, 3),
        ParamInfo::text("light_png", "a PNG file as light texture (replaces light_texture)"),
        ParamInfo::text("shadow_png", "a PNG file as shadow texture (replaces shadow_texture)"),
        ParamInfo::choice("variant", "shadow: band around [ta_l, ta_u]; highlight: band of the "
                                     "same width centred on t_h, the program's texture (else "
                                     "the shadow texture) below it and none in the highlight",
                          {"shadow", "highlight"}, 0),
        ParamInfo::choice("space", "where the textures lie: screen (constant stroke width, "
                                   "any program) or object (the program's texcoords; only for "
                                   "textured objects, others use screen)",
                          {"screen", "object"}, 0),
        ParamInfo::number("texture_scale", "pattern density: screen texels per pixel, or tiles "
                                           "per 1/8 texcoord unit",
                          1.0, 0.1, 16.0),
    };
    return info;
}

void TexturedStyle::prepareLayer(StyleContext& ctx, Layer& layer, const char* choice,
                                 const char* png)
{
    layer.source = Source(std::clamp(int(std::lround(ctx.param("textured", choice))), 0,
                                     int(kSources.size()) - 1));
    const std::string path = ctx.text("textured", png);
    if (!path.empty()) {
        std::string why;
        if (GlTexture::loadPng(path, false, layer.image, why)) {
            layer.source = Paper; // any non-program source: the image decides the mode
            return;
        }
        NPRGL_ERROR("textured: cannot use %s=%s (%s); using the %s texture instead", png,
                    path.c_str(), why.c_str(), kSources[size_t(layer.source)].c_str());
    }
    layer.image = procedural(layer.source);
}

bool TexturedStyle::layerMipmaps() const
{
    // In screen space at a scale <= 1 a texel covers a pixel or more: never minified.
    return mObjectSpace || mScale > 1.0f;
}

// Modes: 0 blank, 1 grey pattern, 2 program texture, 3 colour pattern.
std::string TexturedStyle::layerFunction(const char* name, const Layer& layer, int mode,
                                         const char* sampler, bool objectSpace) const
{
    auto f = [](float v) { return ShadingCommon::glslFloat(v); };
    std::string body;
    if (mode == 0) {
        body = "    return vec3(1.0);\n";
    } else if (mode == 2) {
        body = "    vec4 t = texture(programTex, uv);\n"
               "    return mix(vec3(1.0), t.rgb, t.a);\n";
    } else {
        // Object space: the program's texcoords, 8 tiles per unit; screen space: one texel
        // per pixel at scale 1, anchored at the object's origin, one level of detail.
        std::string fetch;
        if (objectSpace) {
            fetch = std::string("texture(") + sampler + ", uv * 8.0 * " + f(mScale) + ")";
        } else {
            const glm::vec2 step = mScale / glm::vec2(layer.image.width, layer.image.height);
            fetch = std::string("textureLod(") + sampler + ", (gl_FragCoord.xy - anchor) * " +
                    ShadingCommon::glslVec2(step) + ", " +
                    f(std::max(std::log2(mScale), 0.0f)) + ")";
        }
        body = mode == 1 ? "    return vec3(" + fetch + ".r);\n"
                         : "    vec4 t = " + fetch + ";\n" +
                               "    return mix(vec3(1.0), t.rgb, t.a); // transparent: shading\n";
    }
    return std::string("vec3 ") + name + "()\n{\n" + body + "}\n";
}

std::string TexturedStyle::fragmentSource(bool textured, int lights) const
{
    auto f = [](float v) { return ShadingCommon::glslFloat(v); };
    auto flag = [](const char* name, bool on) {
        return std::string("#define ") + name + (on ? " 1\n" : " 0\n");
    };
    int lightMode = modeOf(mLight.source, mLight.image, textured);
    int shadowMode = modeOf(mShadow.source, mShadow.image, textured);
    if (mHighlightVariant) {
        // The detail below the highlight band, nothing inside the highlight.
        if (textured) shadowMode = 2;
        lightMode = 0;
    }
    // Untextured objects have no meaningful texcoords: their patterns lie in screen space.
    const bool objectSpace = mObjectSpace && textured;
    std::string s = "#version 130\n";
    s += "#define TONES " + std::to_string(mTones) + "\n";
    s += flag("TINT", mTint);
    s += flag("ASYMMETRIC", mAsymmetric);
    s += flag("PROGRAM_TEXTURE", textured);
    s += "const float diffuseThreshold = " + f(mDiffuseThreshold) + ";\n";
    s += "const float highlightThreshold = " + f(mHighlightThreshold) + ";\n";
    s += "const float shadowScale = " + f(mShadowScale) + ";\n";
    s += "const float highlightMix = " + f(mHighlightMix) + ";\n";
    s += "const float bandLow = " + f(mBandLow) + ";\n";   // ta_l
    s += "const float bandHigh = " + f(mBandHigh) + ";\n"; // ta_u
    s += "const float falloff = " + f(mFalloff) + ";\n";
    s += ShadingCommon::normalFunction(lights);
    s += ShadingCommon::fogFunction();
    s += "uniform vec3 lightDir;\n"
         "uniform sampler2D lightTex;\n"
         "uniform sampler2D shadowTex;\n"
         "uniform sampler2D programTex;\n"
         "uniform vec2 anchor; // window pixel of the object's origin\n"
         "in vec3 eyeNormal;\n"
         "in vec4 baseColor;\n"
         "in vec2 uv;\n"
         "out vec4 fragColor;\n";
    s += layerFunction("lightLayer", mLight, lightMode, "lightTex", objectSpace);
    s += layerFunction("shadowLayer", mShadow, shadowMode, "shadowTex", objectSpace);
    return s + kFragment;
}

bool TexturedStyle::buildVariant(const GlFunctions& gl, int k, std::string& error)
{
    const std::string fragment = fragmentSource(k % 2 == 1, ShadingCommon::variantLights(k));
    Variant& variant = mVariants[k];
    if (!ShadingCommon::buildProgram(gl, variant.program, variant.u, fragment, error)) {
        return false;
    }
    variant.anchor = variant.program.uniform(gl, "anchor");
    variant.lightTex = variant.program.uniform(gl, "lightTex");
    variant.shadowTex = variant.program.uniform(gl, "shadowTex");
    return true;
}

bool TexturedStyle::init(StyleContext& ctx, std::string& error)
{
    mTones = int(std::lround(ctx.param("textured", "tones"))) <= 2 ? 2 : 3;
    mReflections = ctx.param("textured", "reflections") >= 0.5;
    mDiffuseThreshold = float(ctx.param("textured", "diffuse_threshold"));
    mHighlightThreshold = float(ctx.param("textured", "highlight_threshold"));
    if (mDiffuseThreshold >= mHighlightThreshold) {
        const float td = std::min(mDiffuseThreshold, 0.98f);
        NPRGL_WARN("textured: diffuse_threshold (%.3g) must be below highlight_threshold "
                   "(%.3g); using %.3g and %.3g",
                   double(mDiffuseThreshold), double(mHighlightThreshold), double(td),
                   double(td + 0.02f));
        mDiffuseThreshold = td;
        mHighlightThreshold = td + 0.02f;
    }
    mShadowScale = float(ctx.param("textured", "shadow_scale"));
    mHighlightMix = float(ctx.param("textured", "highlight_mix"));
    mTint = ctx.param("textured", "tint") >= 0.5;
    mBandLow = float(ctx.param("textured", "alpha_low"));
    mBandHigh = float(ctx.param("textured", "alpha_high"));
    if (mBandLow > mBandHigh) {
        NPRGL_WARN("textured: alpha_low (%.3g) is above alpha_high (%.3g); swapping them",
                   double(mBandLow), double(mBandHigh));
        std::swap(mBandLow, mBandHigh);
    }
    mAsymmetric = ctx.param("textured", "transition") >= 0.5;
    mFalloff = float(ctx.param("textured", "falloff"));
    mHighlightVariant = ctx.param("textured", "variant") >= 0.5;
    if (mHighlightVariant) {
        const float half = 0.5f * (mBandHigh - mBandLow);
        mBandLow = mHighlightThreshold - half;
        mBandHigh = mHighlightThreshold + half;
        mTones = 3;
    }
    mObjectSpace = ctx.param("textured", "space") >= 0.5;
    mScale = float(ctx.param("textured", "texture_scale"));
    prepareLayer(ctx, mLight, "light_texture", "light_png");
    prepareLayer(ctx, mShadow, "shadow_texture", "shadow_png");

    // The programs know the layers' sizes, so they come after them.
    const GlFunctions& gl = ctx.gl;
    // Unlit objects' variants now; those for lit ones when first needed (variantFor).
    for (int k = 0; k < 2; ++k) {
        if (!buildVariant(gl, k, error)) return false;
    }
    return true;
}

void TexturedStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    if (!mUploaded) {
        // First use: the compositor has saved the program's state around render().
        for (Layer* layer : {&mLight, &mShadow}) {
            if (layer->image.empty()) continue;
            gl.ActiveTexture(layer == &mLight ? GL_TEXTURE1 : GL_TEXTURE2);
            layer->texture.upload(gl, layer->image, layerMipmaps());
        }
        mUploaded = true;
    }
    gl.ActiveTexture(GL_TEXTURE1);
    gl.BindTexture(GL_TEXTURE_2D, mLight.texture.id());
    gl.ActiveTexture(GL_TEXTURE2);
    gl.BindTexture(GL_TEXTURE_2D, mShadow.texture.id());
    gl.ActiveTexture(GL_TEXTURE0);
    GLuint current = 0;
    for (const SceneObject& listed : scene.objects) {
        const SceneObject& object = ShadingCommon::withGenerated(listed, mReflections, mReflected);
        const bool textured = object.textured();
        Variant& variant = ShadingCommon::variantFor(
            mVariants, mVariantsFailed, textured, object,
            [&](int k, std::string& error) { return buildVariant(gl, k, error); });
        if (variant.program.id() != current) {
            current = variant.program.id();
            gl.UseProgram(current);
            // The program's texture is unit 0, the default of sampler uniforms.
            if (!variant.configured) {
                gl.Uniform1i(variant.lightTex, 1);
                gl.Uniform1i(variant.shadowTex, 2);
            }
            variant.configured = true;
        }
        variant.u.set(gl, object);
        const glm::vec2 anchor = ShadingCommon::screenAnchor(object, scene.viewport);
        gl.Uniform2f(variant.anchor, anchor.x, anchor.y);
        // The program's textures keep their own filtering and wrapping; both sides are
        // drawn in one pass (shadingNormal).
        ShadingCommon::draw(ctx, object, variant.u, textured);
    }
}

void TexturedStyle::shutdown(StyleContext& ctx)
{
    mLight.texture.destroy(ctx.gl);
    mShadow.texture.destroy(ctx.gl);
    for (Variant& variant : mVariants) variant.program.destroy(ctx.gl);
}

} // namespace nprgl::styles
