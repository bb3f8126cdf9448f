#include "styles/shading/GoochStyle.h"

#include "styles/StyleRegistry.h"

#include <cmath>
#include <string>

namespace nprgl::styles {

namespace {

// Parameters arrive as constants (see fragmentSource()).
const char* kFragment = R"(
uniform vec3 lightDir;
uniform sampler2D detail;
in vec3 eyeNormal;
in vec4 baseColor;
in vec2 uv;
out vec4 fragColor;

void main()
{
    vec3 n = shadingNormal(eyeNormal);
    float d = dot(n, lightDir);
    vec3 k = baseColor.rgb;
    float a = baseColor.a; // the program's, for its alpha test and blending
#if DETAIL
    vec4 t = texture(detail, uv);
    k *= t.rgb;
    a *= t.a;
#endif
    // k_cool = (0, 0, b) + alpha k_d, k_warm = (y, y, 0) + beta k_d, blended by (1 + L.n) / 2.
    vec3 cool = vec3(0.0, 0.0, blue) + alpha * k;
    vec3 warm = vec3(yellow, yellow, 0.0) + beta * k;
    vec3 c = mix(cool, warm, 0.5 * (1.0 + d));
#if HIGHLIGHT
    // Blinn's half vector with the viewer on the eye axis (the tone is already view-free).
    vec3 h = normalize(lightDir + vec3(0.0, 0.0, 1.0));
    c = mix(c, vec3(1.0), pow(max(dot(n, h), 0.0), highlight));
#endif
    fragColor = vec4(min(c, vec3(1.0)), a);
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
    };
    return info;
}

std::string GoochStyle::fragmentSource(bool detail) const
{
    auto f = [](float v) { return ShadingCommon::glslFloat(v); };
    std::string s = "#version 130\n";
    s += std::string("#define DETAIL ") + (detail ? "1" : "0") + "\n";
    s += std::string("#define HIGHLIGHT ") + (mHighlight > 0.0f ? "1" : "0") + "\n";
    s += "const float blue = " + f(mBlue) + ";\n";
    s += "const float yellow = " + f(mYellow) + ";\n";
    s += "const float alpha = " + f(mAlpha) + ";\n";
    s += "const float beta = " + f(mBeta) + ";\n";
    s += "const float highlight = " + f(mHighlight) + ";\n";
    return s + ShadingCommon::normalFunction() + kFragment;
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
    for (int v = 0; v < (mDetail ? 2 : 1); ++v) {
        const std::string fragment = fragmentSource(v == 1);
        Variant& variant = mVariants[v];
        if (!variant.program.build(gl, ShadingCommon::vertexShader(), fragment.c_str(),
                                   error)) {
            return false;
        }
        variant.u.find(gl, variant.program.id());
    }
    return true;
}

void GoochStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    const bool frontIsCcw = ShadingCommon::beginTwoSided(gl);
    GLuint current = 0;
    for (const SceneObject& object : scene.objects) {
        const bool textured = object.textured() && mDetail;
        const Variant& variant = mVariants[textured ? 1 : 0];
        if (variant.program.id() != current) {
            current = variant.program.id();
            gl.UseProgram(current);
        }
        variant.u.set(gl, object, frontIsCcw);
        // The program's textures keep their own filtering and wrapping; both sides are
        // drawn in one pass (shadingNormal).
        if (textured) {
            ShadingCommon::drawTextured(ctx, object);
        } else {
            ctx.meshes.draw(gl, *object.mesh);
        }
    }
}

void GoochStyle::shutdown(StyleContext& ctx)
{
    for (Variant& v : mVariants) v.program.destroy(ctx.gl);
}

} // namespace nprgl::styles
