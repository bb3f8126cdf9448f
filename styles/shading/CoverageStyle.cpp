#include "styles/shading/CoverageStyle.h"

#include "styles/StyleRegistry.h"

#include <cmath>

namespace nprgl::styles {

namespace {

const char* kFragment = R"(
uniform vec3 lightDir;
uniform vec3 tint;
uniform sampler2D detail;
uniform bool textured;
in vec3 eyeNormal;
in vec4 baseColor;
in vec2 uv;
out vec4 fragColor;

void main()
{
    vec3 n = shadingNormal(eyeNormal);
    // The program's alpha, for its alpha test: a cut-out covers only what it shows.
    float alpha = baseColor.a * (textured ? texture(detail, uv).a : 1.0);
    fragColor = vec4(tint * (0.65 + 0.35 * max(dot(n, lightDir), 0.0)), alpha);
}
)";

std::unique_ptr<Style> create() { return std::make_unique<CoverageStyle>(); }

} // namespace

StyleInfo coverageStyleInfo()
{
    StyleInfo info;
    info.name = "coverage";
    info.summary = "debug: each styled object in a colour of its own, every 3D draw left as "
                   "the program draws it in red";
    info.role = StyleRole::Shading;
    info.create = &create;
    return info;
}

glm::vec3 CoverageStyle::colourOf(uint32_t id)
{
    // Golden-ratio steps over the hues from yellow (60 degrees) to violet (280): neighbours
    // differ, and none is red.
    const float t = std::fmod(float(id) * 0.6180340f, 1.0f);
    const float hue = 60.0f + 220.0f * t;
    auto channel = [hue](float n) {
        const float k = std::fmod(n + hue / 60.0f, 6.0f);
        return 0.85f - 0.6f * std::max(0.0f, std::min({k, 4.0f - k, 1.0f}));
    };
    return {channel(5.0f), channel(3.0f), channel(1.0f)};
}

bool CoverageStyle::init(StyleContext& ctx, std::string& error)
{
    const std::string fragment =
        std::string("#version 130\n") + ShadingCommon::normalFunction() + kFragment;
    if (!mProgram.build(ctx.gl, ShadingCommon::vertexShader(), fragment.c_str(), error)) {
        return false;
    }
    mU.find(ctx.gl, mProgram.id());
    mTint = mProgram.uniform(ctx.gl, "tint");
    mTextured = mProgram.uniform(ctx.gl, "textured");
    return true;
}

void CoverageStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    gl.UseProgram(mProgram.id());
    for (const SceneObject& object : scene.objects) {
        mU.set(gl, object);
        const glm::vec3 c = colourOf(object.id);
        gl.Uniform3f(mTint, c.r, c.g, c.b);
        gl.Uniform1i(mTextured, object.textured() ? 1 : 0);
        ShadingCommon::draw(ctx, object, mU, object.textured());
    }
}

void CoverageStyle::shutdown(StyleContext& ctx) { mProgram.destroy(ctx.gl); }

} // namespace nprgl::styles
