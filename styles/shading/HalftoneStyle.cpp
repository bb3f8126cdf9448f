#include "styles/shading/HalftoneStyle.h"

#include "common/Log.h"
#include "styles/StyleRegistry.h"
#include "styles/shading/ShadingCommon.h"
#include "styles/textures/HalftoneScreens.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace nprgl::styles {

namespace {

const char* kFragment = R"(
uniform vec3 lightDir;
uniform float ambient;    // a
uniform float diffuse;    // d
uniform float gamma;      // alpha of eq. 3.13
uniform float smoothness; // S of eq. 3.14
uniform sampler2D screen; // H: the combined screens A'B'C'
uniform sampler2D detail; // T: the program's texture
uniform bool useDetail;
uniform float detailStrength;
uniform bool objectSpace;
uniform vec2 anchor;      // window pixel of the object's origin
uniform float scale;      // s_H
uniform bool inkFromObject;
uniform vec3 ink;
uniform vec3 paper;
in vec3 eyeNormal;
in vec4 baseColor;
in vec2 uv;
out vec4 fragColor;

void main()
{
    vec3 n = shadingNormal(eyeNormal);
    float I = ambient + pow(clamp((dot(n, lightDir) + 1.0) * 0.5, 0.0, 1.0), gamma) * diffuse;
    float T = 1.0;
    if (useDetail) {
        vec4 t = texture(detail, uv);
        T = mix(1.0, dot(t.rgb, vec3(0.299, 0.587, 0.114)), t.a * detailStrength);
    }
    // Screen coordinates: texcoords x s_H (x 8 tiles per unit) in object space, else window
    // pixels x s_H / tile size anchored at the object's origin.
    vec2 p = objectSpace ? uv * 8.0 * scale
                         : (gl_FragCoord.xy - anchor) * scale / vec2(textureSize(screen, 0));
    float H = texture(screen, p).r;
    float C = clamp(1.0 - smoothness * (1.0 - I * T - H), 0.0, 1.0);
    vec3 inkColor = inkFromObject ? baseColor.rgb * 0.6 : ink;
    fragColor = vec4(mix(inkColor, paper, C), baseColor.a);
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
        ParamInfo::number("detail_strength", "how much T darkens: colour textures made for "
                                             "shading are darker than halftone detail maps",
                          0.6, 0.0, 1.0),
        ParamInfo::choice("space", "where the screen lies: screen (stable primitive size, "
                                   "any program) or object (the program's texcoords x s_H; "
                                   "only for textured objects, others use screen)",
                          {"screen", "object"}, 0),
        ParamInfo::choice("ink", "ink colour: black, or a darkened object colour",
                          {"black", "object"}, 0),
        ParamInfo::text("paper_color", "paper colour, hex rrggbb", "faf7ee"),
    };
    return info;
}

bool HalftoneStyle::init(StyleContext& ctx, std::string& error)
{
    const std::string fragment =
        std::string("#version 130\n") + ShadingCommon::normalFunction() + kFragment;
    if (!mProgram.build(ctx.gl, ShadingCommon::vertexShader(), fragment.c_str(), error)) {
        return false;
    }
    const GlFunctions& gl = ctx.gl;
    auto at = [&](const char* name) { return mProgram.uniform(gl, name); };
    mU = {at("modelview"), at("projection"), at("normalMatrix"), at("lightDir"), at("ambient"),
          at("diffuse"),   at("gamma"),      at("smoothness"),   at("screen"),   at("detail"),
          at("useDetail"), at("objectSpace"), at("anchor"),      at("scale"),
          at("inkFromObject"), at("ink"),    at("paper"),        at("detailStrength")};

    mAmbient = float(ctx.param("halftone", "ambient"));
    mDiffuse = float(ctx.param("halftone", "diffuse"));
    mGamma = float(ctx.param("halftone", "gamma"));
    mSmoothness = float(ctx.param("halftone", "smoothness"));
    mScale = float(ctx.param("halftone", "screen_scale"));
    mDetail = ctx.param("halftone", "detail") >= 0.5;
    mDetailStrength = float(ctx.param("halftone", "detail_strength"));
    mObjectSpace = ctx.param("halftone", "space") >= 0.5;
    mInkFromObject = ctx.param("halftone", "ink") >= 0.5;
    const std::string paper = ctx.text("halftone", "paper_color");
    if (!ShadingCommon::parseColor(paper, mPaper)) {
        NPRGL_ERROR("halftone: paper_color='%s' is not a hex colour rrggbb; using white",
                    paper.c_str());
        mPaper = glm::vec3(1.0f);
    }

    static const char* kPatterns[] = {"dots", "lines", "noise", "bricks"};
    const int index = std::clamp(int(std::lround(ctx.param("halftone", "pattern"))), 0, 3);
    const std::string png = ctx.text("halftone", "screen_png");
    if (!png.empty()) {
        std::string why;
        if (loadScreens(png, mScreenImage, why)) return true;
        NPRGL_ERROR("halftone: cannot use screen_png=%s (%s); using the procedural '%s' screens",
                    png.c_str(), why.c_str(), kPatterns[index]);
    }
    HalftoneScreens::Pattern pattern = HalftoneScreens::Pattern::Dots;
    HalftoneScreens::parsePattern(kPatterns[index], pattern);
    mScreenImage = HalftoneScreens::combine(HalftoneScreens::make(pattern));
    return true;
}

void HalftoneStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    gl.ActiveTexture(GL_TEXTURE1);
    if (!mScreen.valid()) {
        // First use: the compositor has saved the program's state around render().
        mScreen.upload(gl, mScreenImage);
    }
    gl.BindTexture(GL_TEXTURE_2D, mScreen.id());
    gl.ActiveTexture(GL_TEXTURE0);
    gl.UseProgram(mProgram.id());
    gl.Uniform1f(mU.ambient, mAmbient);
    gl.Uniform1f(mU.diffuse, mDiffuse);
    gl.Uniform1f(mU.gamma, mGamma);
    gl.Uniform1f(mU.smoothness, mSmoothness);
    gl.Uniform1f(mU.scale, mScale);
    gl.Uniform1i(mU.screen, 1);
    gl.Uniform1i(mU.detail, 0);
    gl.Uniform1i(mU.inkFromObject, mInkFromObject ? 1 : 0);
    gl.Uniform1f(mU.detailStrength, mDetailStrength);
    gl.Uniform3f(mU.ink, mInk.r, mInk.g, mInk.b);
    gl.Uniform3f(mU.paper, mPaper.r, mPaper.g, mPaper.b);
    const bool frontIsCcw = ShadingCommon::beginTwoSided(gl);
    for (const SceneObject& object : scene.objects) {
        gl.UniformMatrix4fv(mU.modelview, 1, GL_FALSE, glm::value_ptr(object.modelview));
        gl.UniformMatrix4fv(mU.projection, 1, GL_FALSE, glm::value_ptr(object.projection));
        const glm::mat3 normalMatrix = ShadingCommon::normalMatrix(object.modelview);
        gl.UniformMatrix3fv(mU.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
        gl.Uniform3fv(mU.lightDir, 1, glm::value_ptr(object.lightDir));
        const glm::vec2 anchor = ShadingCommon::screenAnchor(object, scene.viewport);
        gl.Uniform2f(mU.anchor, anchor.x, anchor.y);
        const bool textured = object.texture != 0;
        gl.Uniform1i(mU.objectSpace, mObjectSpace && textured ? 1 : 0);
        gl.Uniform1i(mU.useDetail, mDetail && textured ? 1 : 0);
        if (textured) gl.BindTexture(GL_TEXTURE_2D, object.texture);
        ShadingCommon::drawTwoSided(ctx, *object.mesh, frontIsCcw);
    }
}

void HalftoneStyle::shutdown(StyleContext& ctx)
{
    mScreen.destroy(ctx.gl);
    mProgram.destroy(ctx.gl);
}

} // namespace nprgl::styles
