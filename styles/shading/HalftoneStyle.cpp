#include "styles/shading/HalftoneStyle.h"

#include "common/Log.h"
#include "styles/StyleRegistry.h"
#include "styles/shading/ShadingCommon.h"
#include "styles/textures/HalftoneScreens.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace nprgl::styles {

namespace {

// The parameters arrive as #defines and constants (see fragmentSource()).
const char* kFragment = R"(
uniform vec3 lightDir;
uniform sampler2D screen; // H: the combined screens A'B'C'
uniform sampler2D detail; // T: the program's texture
uniform vec2 anchor;      // window pixel of the object's origin
in vec3 eyeNormal;
in vec4 baseColor;
in vec2 uv;
out vec4 fragColor;

void main()
{
    vec3 n = shadingNormal(eyeNormal);
    float x = clamp((litDot(n, lightDir) + 1.0) * 0.5, 0.0, 1.0);
#if GAMMA_ONE
    float I = ambient + x * diffuse;
#else
    float I = ambient + pow(x, gamma) * diffuse;
#endif
#if DETAIL
    vec4 t = texture(detail, uv);
    float T = mix(1.0, dot(t.rgb, vec3(0.299, 0.587, 0.114)), t.a * detailStrength);
    float IT = I * T;
    float alpha = baseColor.a * t.a; // the program's, for its alpha test and blending
#else
    float IT = I;
    float alpha = baseColor.a;
#endif
    // Screen coordinates: texcoords x s_H (x 8 tiles per unit) in object space, else window
    // pixels x s_H / tile size anchored at the object's origin, where the level of detail
    // is the same everywhere.
#if OBJECT_SPACE
    float H = texture(screen, uv * 8.0 * scale).r;
#else
    float H = textureLod(screen, (gl_FragCoord.xy - anchor) * screenStep, screenLod).r;
#endif
    float C = clamp(1.0 - smoothness * (1.0 - IT - H), 0.0, 1.0);
    fragColor = vec4(programFog(mix(INK_COLOR, paper, C), eyePosition), alpha);
}
)";

std::unique_ptr<Style> create() { return std::make_unique<HalftoneStyle>(); }

// "a.png" is used as the combined screen H; "a.png;b.png;c.png" are the three screens.
bool loadScreens(const std::string& text, TextureImage& out, std::string& error)
{
    HalftoneScreens::Set set;
    TextureImage* slots[3] = {&set.a, &set.b, &set.c};
    size_t start = 0;
    int count = 0;
    while (start <= text.size() && count < 3) {
        const size_t end = std::min(text.find(';', start), text.size());
        const std::string path = text.substr(start, end - start);
        if (!path.empty() && !GlTexture::loadPng(path, true, *slots[count], error)) {
            error = path + ": " + error;
            return false;
        }
        ++count;
        start = end + 1;
    }
    if (count == 1) {
        out = set.a;
        return !out.empty();
    }
    out = HalftoneScreens::combine(set);
    return true;
}

} // namespace

StyleInfo halftoneStyleInfo()
{
    StyleInfo info;
    info.name = "halftone";
    info.summary = "half-toning with three screens: dots, lines, charcoal noise, bricks "
                   "(thesis 3.3)";
    info.role = StyleRole::Shading;
    info.create = &create;
    info.params = {
        ParamInfo::choice("pattern", "the screens: dots (three sizes), lines (three "
                                     "densities), noise (charcoal), bricks",
                          {"dots", "lines", "noise", "bricks"}, 0),
        ParamInfo::text("screen_png", "PNG screen(s) instead of the pattern: one file is the "
                                      "combined screen H, 'a.png;b.png;c.png' the screens A, B, C"),
        ParamInfo::number("smoothness", "S: steepness of the thresholding (eq. 3.14); higher "
                                        "is crisper",
                          16.0, 1.0, 64.0),
        ParamInfo::number("screen_scale", "s_H: higher values give finer primitives", 1.0, 0.1,
                          16.0),
        ParamInfo::number("ambient", "a: ambient intensity (eq. 3.13)", 0.0, 0.0, 1.0),
        ParamInfo::number("diffuse", "d: diffuse intensity (eq. 3.13)", 1.0, 0.0, 2.0),
        ParamInfo::number("gamma", "alpha: gamma of the diffuse term; > 1 darkens the mid "
                                   "tones, < 1 lightens them",
                          1.0, 0.1, 10.0),
        ParamInfo::flag("detail", "the program's texture as detail map T", true),
        ShadingCommon::reflectionsParam(),
        ParamInfo::number("detail_strength", "how much T darkens: colour textures made for "
                                             "shading are darker than halftone detail maps",
                          0.6, 0.0, 1.0),
        ParamInfo::choice("space", "where the screen lies: screen (stable primitive size, "
                                   "any program) or object (the program's texcoords x s_H; "
                                   "only for textured objects, others use screen)",
                          {"screen", "object"}, 0),
        ParamInfo::choice("ink", "ink colour: black, or a darkened object colour",
                          {"black", "object"}, 0),
        ParamInfo::colour("paper_color", "paper colour, hex rrggbb", "faf7ee"),
    };
    return info;
}

bool HalftoneStyle::screenMipmaps() const
{
    // In screen space at s_H <= 1 a texel covers a pixel or more: never minified.
    return mObjectSpace || mScale > 1.0f;
}

std::string HalftoneStyle::fragmentSource(bool textured, int lights) const
{
    auto f = [](float v) { return ShadingCommon::glslFloat(v); };
    auto flag = [](const char* name, bool on) {
        return std::string("#define ") + name + (on ? " 1\n" : " 0\n");
    };
    std::string s = "#version 130\n";
    s += flag("DETAIL", mDetail && textured);
    s += flag("OBJECT_SPACE", mObjectSpace && textured);
    s += flag("GAMMA_ONE", mGamma == 1.0f);
    s += "const float ambient = " + f(mAmbient) + ";\n";
    s += "const float diffuse = " + f(mDiffuse) + ";\n";
    s += "const float gamma = " + f(mGamma) + ";\n";
    s += "const float smoothness = " + f(mSmoothness) + ";\n";
    s += "const float scale = " + f(mScale) + ";\n";
    s += "const float detailStrength = " + f(mDetailStrength) + ";\n";
    s += "const vec2 screenStep = " +
         ShadingCommon::glslVec2(mScale / glm::vec2(mScreenImage.width, mScreenImage.height)) +
         ";\n";
    // The screen-space derivative of the coordinates is s_H texels per pixel.
    s += "const float screenLod = " + f(std::max(std::log2(mScale), 0.0f)) + ";\n";
    s += "const vec3 paper = " + ShadingCommon::glslVec3(mPaper) + ";\n";
    s += std::string("#define INK_COLOR ") +
         (mInkFromObject ? "(baseColor.rgb * 0.6)" : ShadingCommon::glslVec3(mInk)) + "\n";
    return s + ShadingCommon::normalFunction(lights) + ShadingCommon::fogFunction() +
           kFragment;
}

bool HalftoneStyle::buildVariant(const GlFunctions& gl, int k, std::string& error)
{
    const std::string fragment = fragmentSource(k % 2 == 1, ShadingCommon::variantLights(k));
    Variant& variant = mVariants[k];
    if (!ShadingCommon::buildProgram(gl, variant.program, variant.u, fragment, error)) {
        return false;
    }
    variant.anchor = variant.program.uniform(gl, "anchor");
    variant.screen = variant.program.uniform(gl, "screen");
    return true;
}

bool HalftoneStyle::init(StyleContext& ctx, std::string& error)
{
    mAmbient = float(ctx.param("halftone", "ambient"));
    mDiffuse = float(ctx.param("halftone", "diffuse"));
    mGamma = float(ctx.param("halftone", "gamma"));
    mSmoothness = float(ctx.param("halftone", "smoothness"));
    mScale = float(ctx.param("halftone", "screen_scale"));
    mDetail = ctx.param("halftone", "detail") >= 0.5;
    mReflections = ctx.param("halftone", "reflections") >= 0.5;
    mDetailStrength = float(ctx.param("halftone", "detail_strength"));
    mObjectSpace = ctx.param("halftone", "space") >= 0.5;
    mInkFromObject = ctx.param("halftone", "ink") >= 0.5;
    const std::string paper = ctx.text("halftone", "paper_color");
    if (!ParamInfo::parseColour(paper, mPaper)) {
        NPRGL_ERROR("halftone: paper_color='%s' is not a hex colour rrggbb; using white",
                    paper.c_str());
        mPaper = glm::vec3(1.0f);
    }

    static const char* kPatterns[] = {"dots", "lines", "noise", "bricks"};
    const int index = std::clamp(int(std::lround(ctx.param("halftone", "pattern"))), 0, 3);
    const std::string png = ctx.text("halftone", "screen_png");
    bool loaded = false;
    if (!png.empty()) {
        std::string why;
        loaded = loadScreens(png, mScreenImage, why);
        if (!loaded) {
            NPRGL_ERROR("halftone: cannot use screen_png=%s (%s); using the procedural '%s' "
                        "screens",
                        png.c_str(), why.c_str(), kPatterns[index]);
        }
    }
    if (!loaded) {
        HalftoneScreens::Pattern pattern = HalftoneScreens::Pattern::Dots;
        HalftoneScreens::parsePattern(kPatterns[index], pattern);
        mScreenImage = HalftoneScreens::combine(HalftoneScreens::make(pattern));
    }

    // The programs know the screen's size, so they come after it.
    const GlFunctions& gl = ctx.gl;
    // Unlit objects' variants now; those for lit ones when first needed (variantFor).
    for (int k = 0; k < 2; ++k) {
        if (!buildVariant(gl, k, error)) return false;
    }
    return true;
}

void HalftoneStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    gl.ActiveTexture(GL_TEXTURE1);
    if (!mScreen.valid()) {
        // First use: the compositor has saved the program's state around render().
        mScreen.upload(gl, mScreenImage, screenMipmaps());
    }
    gl.BindTexture(GL_TEXTURE_2D, mScreen.id());
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
            // The detail map is unit 0, the default of sampler uniforms.
            if (!variant.configured) gl.Uniform1i(variant.screen, 1);
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

void HalftoneStyle::shutdown(StyleContext& ctx)
{
    mScreen.destroy(ctx.gl);
    for (Variant& variant : mVariants) variant.program.destroy(ctx.gl);
}

} // namespace nprgl::styles
