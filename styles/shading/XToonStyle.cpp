#include "styles/shading/XToonStyle.h"

#include "common/Log.h"
#include "styles/StyleRegistry.h"
#include "styles/textures/XToonTexture.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace nprgl::styles {

namespace {

constexpr const char* kStyle = "xtoon";

// Parameters arrive as constants and #defines (see fragmentSource()).
const char* kFragment = R"(
uniform vec3 lightDir;
uniform sampler2D detail;  // unit 0: the program's texture
uniform sampler2D toneMap; // unit 1
uniform vec2 depthRange;   // eye distances of v = 0 and v = 1
uniform float perspectiveView;
in vec3 eyeNormal;
in vec4 baseColor;
in vec2 uv;
out vec4 fragColor;

void main()
{
    vec3 n = shadingNormal(eyeNormal);
    float u = clamp(0.5 * litDot(n, lightDir) + 0.5, 0.0, 1.0);
#if ORIENTATION
    vec3 toEye = perspectiveView > 0.5 ? normalize(-eyePosition) : vec3(0.0, 0.0, 1.0);
    float v = 1.0 - pow(abs(dot(n, toEye)), exponent);
#else
    float v = clamp((-eyePosition.z - depthRange.x) / max(depthRange.y - depthRange.x, 1e-6),
                    0.0, 1.0);
#endif
    vec3 c = texture(toneMap, vec2(u, v)).rgb * baseColor.rgb;
    float alpha = baseColor.a;
#if DETAIL
    vec4 t = texture(detail, uv);
    c *= t.rgb;
    alpha *= t.a;
#endif
    fragColor = vec4(programFog(c, eyePosition), alpha);
}
)";

std::unique_ptr<Style> create() { return std::make_unique<XToonStyle>(); }

} // namespace

StyleInfo xtoonStyleInfo()
{
    StyleInfo info;
    info.name = kStyle;
    info.summary = "X-Toon: a 2D tone map indexed by L.n and by depth (level of abstraction) "
                   "or view orientation (back-light, rims) (Barla et al. 2006)";
    info.role = StyleRole::Shading;
    info.create = &create;
    info.params = {
        ParamInfo::choice("mode", "the tone map's second axis: depth (eye distance from near "
                                  "to far) or orientation (1 - |n.v|^r)",
                          {"depth", "orientation"}, 0),
        ParamInfo::text("texture", "PNG tone map (x: L.n from -1 to 1, y from the top: full "
                                   "detail to the most abstract); empty: the generated one"),
        ParamInfo::number("near", "depth: eye distance of full detail (0: the scene's nearest "
                                  "point)",
                          0.0, 0.0, 1e6),
        ParamInfo::number("far", "depth: eye distance of the most abstract tone (0: the scene's "
                                 "farthest point)",
                          0.0, 0.0, 1e6),
        ParamInfo::number("r", "orientation: exponent of |n.v| (higher: wider rims)", 2.0, 0.1,
                          32.0),
        ParamInfo::number("bands", "cel bands of the generated tone map (not of a texture=)", 3,
                          XToonTexture::kMinBands, XToonTexture::kMaxBands),
        ParamInfo::flag("detail", "the program's own texture modulates the tones", true),
        ShadingCommon::reflectionsParam(),
    };
    return info;
}

std::string XToonStyle::fragmentSource(bool detail, int lights) const
{
    std::string s = "#version 130\n";
    s += std::string("#define DETAIL ") + (detail ? "1" : "0") + "\n";
    s += std::string("#define ORIENTATION ") + (mOrientation ? "1" : "0") + "\n";
    s += "const float exponent = " + ShadingCommon::glslFloat(mExponent) + ";\n";
    return s + ShadingCommon::normalFunction(lights) + ShadingCommon::fogFunction() +
           kFragment;
}

bool XToonStyle::buildVariant(const GlFunctions& gl, int k, std::string& error)
{
    const std::string fragment = fragmentSource(k % 2 == 1, ShadingCommon::variantLights(k));
    Variant& variant = mVariants[k];
    if (!ShadingCommon::buildProgram(gl, variant.program, variant.u, fragment, error)) {
        return false;
    }
    variant.depthRange = variant.program.uniform(gl, "depthRange");
    variant.perspectiveView = variant.program.uniform(gl, "perspectiveView");
    variant.toneMap = variant.program.uniform(gl, "toneMap");
    return true;
}

bool XToonStyle::init(StyleContext& ctx, std::string& error)
{
    const GlFunctions& gl = ctx.gl;
    mOrientation = std::lround(ctx.param(kStyle, "mode")) == 1;
    mNear = float(ctx.param(kStyle, "near"));
    mFar = float(ctx.param(kStyle, "far"));
    mExponent = float(ctx.param(kStyle, "r"));
    mDetail = ctx.param(kStyle, "detail") >= 0.5;
    mReflections = ctx.param(kStyle, "reflections") >= 0.5;
    const int bands = int(std::lround(ctx.param(kStyle, "bands")));
    if (mFar > 0.0f && mFar <= mNear) {
        NPRGL_WARN("xtoon: far (%g) must lie beyond near (%g); using the scene's range",
                   double(mFar), double(mNear));
        mNear = mFar = 0.0f;
    }
    const std::string path = ctx.text(kStyle, "texture");
    std::string why;
    if (path.empty() || !GlTexture::loadPng(path, false, mToneImage, why)) {
        if (!path.empty()) {
            NPRGL_ERROR("xtoon: cannot use texture=%s (%s); using the generated tone map",
                        path.c_str(), why.c_str());
        }
        mToneImage = XToonTexture::generate(bands);
    }
    // Unlit objects' variants now; those for lit ones when first needed (variantFor).
    for (int k = 0; k < (mDetail ? 2 : 1); ++k) {
        if (!buildVariant(gl, k, error)) return false;
    }
    return true;
}

glm::vec2 XToonStyle::sceneDepthRange(const Scene& scene) const
{
    float nearest = std::numeric_limits<float>::max(), farthest = 0.0f;
    for (const SceneObject& o : scene.objects) {
        const uint32_t n = o.mesh->vertexCount();
        // A few hundred points per object give the range; every vertex would cost as much
        // as the drawing on large meshes.
        const uint32_t step = std::max(1u, n / 256u);
        for (uint32_t v = 0; v < n; v += step) {
            const glm::vec4 e = o.modelview * glm::vec4(o.mesh->position(v), 1.0f);
            const float d = -e.z / (e.w != 0.0f ? e.w : 1.0f);
            if (!std::isfinite(d)) continue;
            nearest = std::min(nearest, d);
            farthest = std::max(farthest, d);
        }
    }
    if (!(farthest > nearest)) return {0.0f, 1.0f};
    return {nearest, farthest};
}

glm::vec2 XToonStyle::depthRange(const Scene& scene)
{
    if (mNear > 0.0f && mFar > 0.0f) return {mNear, mFar}; // checked in init()
    if (mOrientation) return {0.0f, 1.0f};                  // unused
    // An end left at 0 follows the scene, so one configured end can meet the scene's other
    // on the wrong side (near beyond everything drawn, far before it).
    const glm::vec2 range = sceneDepthRange(scene);
    const glm::vec2 configured(mNear > 0.0f ? mNear : range.x, mFar > 0.0f ? mFar : range.y);
    if (configured.y > configured.x) return configured;
    if (!mWarnedRange) {
        NPRGL_WARN("xtoon: near %g and far %g (the scene's where 0) are out of order; using "
                   "the scene's range %g to %g",
                   double(configured.x), double(configured.y), double(range.x), double(range.y));
        mWarnedRange = true;
    }
    return range;
}

void XToonStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    if (!mToneMap.valid()) {
        gl.ActiveTexture(GL_TEXTURE1);
        mToneMap.upload(gl, mToneImage, false);
        // The axes end at the map's edges: no wrapping from lit to shadow.
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
        gl.ActiveTexture(GL_TEXTURE0);
    }
    const glm::vec2 range = depthRange(scene);
    gl.ActiveTexture(GL_TEXTURE1);
    gl.BindTexture(GL_TEXTURE_2D, mToneMap.id());
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
            gl.Uniform1i(variant.toneMap, 1);
            gl.Uniform2f(variant.depthRange, range.x, range.y);
        }
        variant.u.set(gl, object);
        gl.Uniform1f(variant.perspectiveView, object.orthographic() ? 0.0f : 1.0f);
        ShadingCommon::draw(ctx, object, variant.u, textured);
    }
    gl.ActiveTexture(GL_TEXTURE1);
    gl.BindTexture(GL_TEXTURE_2D, 0);
    gl.ActiveTexture(GL_TEXTURE0);
}

void XToonStyle::shutdown(StyleContext& ctx)
{
    for (Variant& v : mVariants) v.program.destroy(ctx.gl);
    mToneMap.destroy(ctx.gl);
}

} // namespace nprgl::styles
