#include "styles/shading/ObjectIdStyle.h"

#include "common/FrameFidelity.h"
#include "styles/StyleRegistry.h"

namespace nprgl::styles {

namespace {

const char* kFragment = R"(#version 130
uniform vec3 idColour;
uniform sampler2D detail;
uniform bool textured;
in vec4 baseColor;
in vec2 uv;
out vec4 fragColor;
void main()
{
    // The program's alpha, for the alpha test the chain applies: a cut-out covers only what
    // it shows.
    float alpha = baseColor.a * (textured ? texture(detail, uv).a : 1.0);
    fragColor = vec4(idColour, alpha);
}
)";

std::unique_ptr<Style> create() { return std::make_unique<ObjectIdStyle>(); }

} // namespace

StyleInfo idsStyleInfo()
{
    StyleInfo info;
    info.name = "ids";
    info.summary = "debug: each styled object flat in a colour encoding its id (what `nprgl "
                   "compare` reads per object)";
    info.role = StyleRole::Shading;
    info.create = &create;
    return info;
}

bool ObjectIdStyle::init(StyleContext& ctx, std::string& error)
{
    if (!mProgram.build(ctx.gl, ShadingCommon::vertexShader(), kFragment, error)) return false;
    mU.find(ctx.gl, mProgram.id());
    mId = mProgram.uniform(ctx.gl, "idColour");
    mTextured = mProgram.uniform(ctx.gl, "textured");
    return true;
}

void ObjectIdStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    // Translucent objects too are written whole: a blended id is no id.
    gl.Disable(GL_BLEND);
    gl.UseProgram(mProgram.id());
    for (const SceneObject& object : scene.objects) {
        if (object.id > FrameFidelity::kMaxId) continue;
        mU.set(gl, object);
        uint8_t rgb[3];
        FrameFidelity::idColour(object.id, rgb);
        gl.Uniform3f(mId, rgb[0] / 255.0f, rgb[1] / 255.0f, rgb[2] / 255.0f);
        gl.Uniform1i(mTextured, object.textured() ? 1 : 0);
        ShadingCommon::draw(ctx, object, mU, object.textured());
    }
}

void ObjectIdStyle::shutdown(StyleContext& ctx) { mProgram.destroy(ctx.gl); }

} // namespace nprgl::styles
