#include "styles/shading/GoochStyle.h"

#include "common/Log.h"
#include "styles/StyleRegistry.h"

#include <cmath>
#include <string>

namespace nprgl::styles {

namespace {

// Parameters arrive as constants (see fragmentSource()).
const char* kFragment = R"(
uniform vec3 lightDir;
uniform sampler2D detail;
uniform sampler2D ramp; // unit 1: the pure tones from cool (left) to warm (right)
in vec3 eyeNormal;
in vec4 baseColor;
in vec2 uv;
out vec4 fragColor;

void main()
{
    vec3 n = shadingNormal(eyeNormal);
    float d = litDot(n, lightDir);
    vec3 k = baseColor.rgb;
    float a = baseColor.a; // the program's, for its alpha test and blending
#if DETAIL
    vec4 t = texture(detail, uv);
    k *= t.rgb;
    a *= t.a;
#endif
    // k_cool = (0, 0, b) + alpha k_d, k_warm = (y, y, 0) + beta k_d, blended by
    // x = (1 + L.n) / 2: the pure tones come from the ramp (generated from b and y, or the
    // user's), the object's share is mixed in by the same x.
    float x = 0.5 * (1.0 + d);
    vec3 c = texture(ramp, vec2(x, 0.5)).rgb + mix(alpha, beta, x) * k;
#if HIGHLIGHT
    // Blinn's half vector with the viewer on the eye axis (the tone is already view-free).
    vec3 h = normalize(lightDir + vec3(0.0, 0.0, 1.0));
    c = mix(c, vec3(1.0), pow(max(dot(n, h), 0.0), highlight));
#endif
    fragColor = vec4(programFog(min(c, vec3(1.0)), eyePosition), a);
}
)";

std::unique_ptr<Style> create() { return std::make_unique<GoochStyle>(); }

} // namespace

StyleInfo goochStyleInfo()
{
    StyleInfo info;
    info.name = "gooch";
    info.summary = "technical illustration: cool-to-warm tones mixed with the object's colour "
                   "(Gooch et al. 1998)";
    info.role = StyleRole::Shading;
    info.create = &create;
    info.params = {
        ParamInfo::number("blue", "b: the blue of the cool tone", 0.4, 0.0, 1.0),
        ParamInfo::number("yellow", "y: the yellow of the warm tone", 0.4, 0.0, 1.0),
        ParamInfo::number("alpha", "share of the object's colour in the cool tone", 0.2, 0.0,
                          1.0),
        ParamInfo::number("beta", "share of the object's colour in the warm tone", 0.6, 0.0, 1.0),
        ParamInfo::number("highlight", "exponent of a white highlight (0: none)", 0.0, 0.0,
                          256.0),
        ParamInfo::flag("detail", "the program's own texture modulates the tones", true),
        ShadingCommon::reflectionsParam(),
        ParamInfo::text("texture", "PNG of the pure tones from cool (left, facing away from "
                                   "the light) to warm (right), its middle row; empty: "
                                   "blue to yellow from b and y"),
    };
    return info;
}

std::string GoochStyle::fragmentSource(bool detail, int lights) const
{
    auto f = [](float v) { return ShadingCommon::glslFloat(v); };
    std::string s = "#version 130\n";
    s += std::string("#define DETAIL ") + (detail ? "1" : "0") + "\n";
    s += std::string("#define HIGHLIGHT ") + (mHighlight > 0.0f ? "1" : "0") + "\n";
    s += "const float alpha = " + f(mAlpha) + ";\n";
    s += "const float beta = " + f(mBeta) + ";\n";
    s += "const float highlight = " + f(mHighlight) + ";\n";
    return s + ShadingCommon::normalFunction(lights) + ShadingCommon::fogFunction() +
           kFragment;
}

bool GoochStyle::buildVariant(const GlFunctions& gl, int k, std::string& error)
{
    const std::string fragment = fragmentSource(k % 2 == 1, ShadingCommon::variantLights(k));
    Variant& variant = mVariants[k];
    if (!ShadingCommon::buildProgram(gl, variant.program, variant.u, fragment, error)) {
        return false;
    }
    variant.ramp = variant.program.uniform(gl, "ramp");
    return true;
}

bool GoochStyle::init(StyleContext& ctx, std::string& error)
{
    const GlFunctions& gl = ctx.gl;
    mBlue = float(ctx.param("gooch", "blue"));
    mYellow = float(ctx.param("gooch", "yellow"));
    mAlpha = float(ctx.param("gooch", "alpha"));
    mBeta = float(ctx.param("gooch", "beta"));
    mHighlight = float(ctx.param("gooch", "highlight"));
    mDetail = ctx.param("gooch", "detail") >= 0.5;
    mReflections = ctx.param("gooch", "reflections") >= 0.5;
    // Unlit objects' variants now; those for lit ones when first needed (variantFor).
    for (int k = 0; k < (mDetail ? 2 : 1); ++k) {
        if (!buildVariant(gl, k, error)) return false;
    }
    const std::string path = ctx.text("gooch", "texture");
    std::string why;
    if (path.empty() || !GlTexture::loadPng(path, false, mRampImage, why)) {
        if (!path.empty()) {
            NPRGL_ERROR("gooch: cannot use texture=%s (%s); using the blue-to-yellow ramp",
                        path.c_str(), why.c_str());
        }
        mRampImage = generatedRamp();
    }
    return true;
}

TextureImage GoochStyle::generatedRamp() const
{
    // (0, 0, b) at the cool end to (y, y, 0) at the warm end, linear in x.
    TextureImage image;
    image.width = 256;
    image.height = 1;
    image.channels = 4;
    image.pixels.resize(256 * 4);
    for (int i = 0; i < 256; ++i) {
        const float x = float(i) / 255.0f;
        uint8_t* p = &image.pixels[size_t(i) * 4];
        p[0] = p[1] = uint8_t(std::lround(255.0f * mYellow * x));
        p[2] = uint8_t(std::lround(255.0f * mBlue * (1.0f - x)));
        p[3] = 255;
    }
    return image;
}

void GoochStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    gl.ActiveTexture(GL_TEXTURE1);
    if (!mRamp.valid()) {
        mRamp.upload(gl, mRampImage, false);
        // The ends are the ends: no wrapping from warm to cool.
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
    gl.BindTexture(GL_TEXTURE_2D, mRamp.id());
    gl.ActiveTexture(GL_TEXTURE0);
    GLuint current = 0;
    for (const SceneObject& listed : scene.objects) {
        const SceneObject& object = ShadingCommon::withGenerated(listed, mReflections, mReflected);
        const bool textured = object.textured() && mDetail;
        Variant& variant = ShadingCommon::variantFor(
            mVariants, mVariantsFailed, textured, object,
            [&](int k, std::string& error) { return buildVariant(gl, k, error); });
        if (variant.program.id() != current) {
            current = variant.program.id();
            gl.UseProgram(current);
            gl.Uniform1i(variant.ramp, 1);
        }
        variant.u.set(gl, object);
        // The program's textures keep their own filtering and wrapping; both sides are
        // drawn in one pass (shadingNormal).
        ShadingCommon::draw(ctx, object, variant.u, textured);
    }
}

void GoochStyle::shutdown(StyleContext& ctx)
{
    for (Variant& v : mVariants) v.program.destroy(ctx.gl);
    mRamp.destroy(ctx.gl);
}

} // namespace nprgl::styles
