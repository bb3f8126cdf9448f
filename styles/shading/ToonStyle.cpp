#include "styles/shading/ToonStyle.h"

#include "common/Log.h"
#include "styles/StyleRegistry.h"
#include "styles/shading/ShadingCommon.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace nprgl::styles {

namespace {

const char* kFragment = R"(
uniform vec3 lightDir;
uniform float diffuseThreshold;
uniform float highlightThreshold;
uniform int tones;
uniform float shadowScale;
uniform float highlightMix;
uniform bool smoothBands;
uniform int detailMode; // 0 off, 1 modulate, 2 decal
uniform sampler2D detail;
uniform bool bandLines;
uniform float lineWidth;
uniform int fixedColors; // bits: shadow, diffuse, highlight
uniform vec3 shadowColor;
uniform vec3 diffuseColor;
uniform vec3 highlightColor;
in vec3 eyeNormal;
in vec4 baseColor;
in vec2 uv;
out vec4 fragColor;

// 0 below the threshold, 1 above; with smoothBands a one-pixel ramp (screen-space
// antialiasing of the band boundary, thesis 3.1.4).
float above(float d, float t, float pixel)
{
    if (!smoothBands) return d < t ? 0.0 : 1.0;
    return clamp((d - t) / pixel + 0.5, 0.0, 1.0);
}

// Ink coverage of a line lineWidth pixels wide centred on the boundary d == t.
float boundaryInk(float d, float t, float pixel)
{
    float dist = abs(d - t) / pixel;
    return clamp(0.5 * lineWidth - dist + 0.5, 0.0, 1.0);
}

void main()
{
    vec3 n = shadingNormal(eyeNormal);
    float d = dot(n, lightDir);
    float pixel = max(fwidth(d), 1e-5);
    vec3 base = baseColor.rgb;
    vec3 cs = (fixedColors & 1) != 0 ? shadowColor : base * shadowScale;
    vec3 cd = (fixedColors & 2) != 0 ? diffuseColor : base;
    vec3 ch = (fixedColors & 4) != 0 ? highlightColor : mix(base, vec3(1.0), highlightMix);
    vec3 c = mix(cs, cd, above(d, diffuseThreshold, pixel));
    if (tones == 3) c = mix(c, ch, above(d, highlightThreshold, pixel));
    if (detailMode != 0) {
        vec4 t = texture(detail, uv);
        c = detailMode == 1 ? c * t.rgb : mix(c, t.rgb, t.a);
    }
    if (bandLines) {
        float ink = boundaryInk(d, diffuseThreshold, pixel);
        if (tones == 3) ink = max(ink, boundaryInk(d, highlightThreshold, pixel));
        c *= 1.0 - ink;
    }
    fragColor = vec4(c, baseColor.a);
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
        ParamInfo::number("diffuse_threshold", "t_d: L.n below it is shadow", 0.0, -1.0, 1.0),
        ParamInfo::number("highlight_threshold",
                          "t_h: L.n above it is highlight (kept above t_d)", 0.92, -1.0, 1.0),
        ParamInfo::number("shadow_scale", "shadow colour = base colour x this", 0.55, 0.0, 1.0),
        ParamInfo::number("highlight_mix", "highlight colour = base mixed with white by this",
                          0.55, 0.0, 1.0),
        ParamInfo::text("shadow_color", "fixed shadow colour, hex rrggbb (empty: derived)"),
        ParamInfo::text("diffuse_color", "fixed diffuse colour, hex rrggbb (empty: the "
                                         "program's colour)"),
        ParamInfo::text("highlight_color", "fixed highlight colour, hex rrggbb (empty: derived)"),
        ParamInfo::choice("band", "band boundaries: nearest (hard, like a nearest-filtered "
                                  "shading texture) or smooth (antialiased over one pixel)",
                          {"nearest", "smooth"}, 1),
        ParamInfo::choice("detail", "the program's own texture as detail: off, modulate "
                                    "(multiplied with the shading) or decal (a sticker on top)",
                          {"off", "modulate", "decal"}, 1),
        ParamInfo::flag("band_lines", "ink lines between the shade bands (thesis fig. 3.8)",
                        false),
        ParamInfo::number("band_line_width", "width of the band lines in pixels", 1.5, 0.5, 8.0),
    };
    return info;
}

bool ToonStyle::init(StyleContext& ctx, std::string& error)
{
    const std::string fragment =
        std::string("#version 130\n") + ShadingCommon::normalFunction() + kFragment;
    if (!mProgram.build(ctx.gl, ShadingCommon::vertexShader(), fragment.c_str(), error)) {
        return false;
    }
    const GlFunctions& gl = ctx.gl;
    auto at = [&](const char* name) { return mProgram.uniform(gl, name); };
    mU = {at("modelview"),   at("projection"),  at("normalMatrix"), at("lightDir"),
          at("diffuseThreshold"), at("highlightThreshold"), at("tones"), at("shadowScale"),
          at("highlightMix"), at("smoothBands"), at("detailMode"),  at("detail"),
          at("bandLines"),   at("lineWidth"),   at("fixedColors"),  at("shadowColor"),
          at("diffuseColor"), at("highlightColor")};

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
    mHighlightMix = float(ctx.param("toon", "highlight_mix"));
    mSmooth = ctx.param("toon", "band") >= 0.5;
    mDetail = int(std::lround(ctx.param("toon", "detail")));
    mBandLines = ctx.param("toon", "band_lines") >= 0.5;
    mLineWidth = float(ctx.param("toon", "band_line_width"));
    const char* colorNames[3] = {"shadow_color", "diffuse_color", "highlight_color"};
    for (int i = 0; i < 3; ++i) {
        const std::string text = ctx.text("toon", colorNames[i]);
        const bool fixed = ShadingCommon::parseColor(text, mColors[i]);
        if (fixed) mFixed |= 1 << i;
        if (!text.empty() && !fixed) {
            NPRGL_ERROR("toon: %s='%s' is not a hex colour rrggbb; using the derived colour",
                        colorNames[i], text.c_str());
        }
    }
    return true;
}

void ToonStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    gl.UseProgram(mProgram.id());
    gl.Uniform1f(mU.diffuseThreshold, mDiffuseThreshold);
    gl.Uniform1f(mU.highlightThreshold, mHighlightThreshold);
    gl.Uniform1i(mU.tones, mTones);
    gl.Uniform1f(mU.shadowScale, mShadowScale);
    gl.Uniform1f(mU.highlightMix, mHighlightMix);
    gl.Uniform1i(mU.smoothBands, mSmooth ? 1 : 0);
    gl.Uniform1i(mU.bandLines, mBandLines ? 1 : 0);
    gl.Uniform1f(mU.lineWidth, mLineWidth);
    gl.Uniform1i(mU.detail, 0);
    gl.Uniform3f(mU.shadowColor, mColors[0].r, mColors[0].g, mColors[0].b);
    gl.Uniform3f(mU.diffuseColor, mColors[1].r, mColors[1].g, mColors[1].b);
    gl.Uniform3f(mU.highlightColor, mColors[2].r, mColors[2].g, mColors[2].b);
    gl.Uniform1i(mU.fixedColors, mFixed);
    gl.ActiveTexture(GL_TEXTURE0);
    const bool frontIsCcw = ShadingCommon::beginTwoSided(gl);
    for (const SceneObject& object : scene.objects) {
        gl.UniformMatrix4fv(mU.modelview, 1, GL_FALSE, glm::value_ptr(object.modelview));
        gl.UniformMatrix4fv(mU.projection, 1, GL_FALSE, glm::value_ptr(object.projection));
        const glm::mat3 normalMatrix = ShadingCommon::normalMatrix(object.modelview);
        gl.UniformMatrix3fv(mU.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
        gl.Uniform3fv(mU.lightDir, 1, glm::value_ptr(object.lightDir));
        const bool textured = object.texture != 0 && mDetail != 0;
        gl.Uniform1i(mU.detailMode, textured ? mDetail : 0);
        // The program's texture keeps its own filtering and wrapping.
        if (textured) gl.BindTexture(GL_TEXTURE_2D, object.texture);
        ShadingCommon::drawTwoSided(ctx, *object.mesh, frontIsCcw);
    }
}

void ToonStyle::shutdown(StyleContext& ctx) { mProgram.destroy(ctx.gl); }

} // namespace nprgl::styles
