#include "styles/shading/PlainShading.h"

namespace nprgl::styles {

namespace {

const char* kFragment = R"(
uniform sampler2D detail;
uniform sampler2D lightmap;
uniform float lightmapped;
in vec4 baseColor;
in vec2 uv;
in vec2 lightUv;
in vec3 eyePosition;
out vec4 fragColor;
void main()
{
    vec4 c = baseColor;
#if TEXTURED
    c *= texture(detail, uv);
#endif
    // GL_MODULATE on the lightmap's unit too.
    if (lightmapped > 0.5) c.rgb *= texture(lightmap, lightUv).rgb;
    fragColor = vec4(programFog(c.rgb, eyePosition), c.a);
}
)";

} // namespace

bool PlainShading::init(const GlFunctions& gl, std::string& error)
{
    for (int textured = 0; textured < 2; ++textured) {
        const std::string fragment = "#version 130\n#define TEXTURED " +
                                     std::to_string(textured) + "\n" +
                                     ShadingCommon::fogFunction() + kFragment;
        Variant& v = mVariants[textured];
        if (!ShadingCommon::buildProgram(gl, v.program, v.u, fragment, error)) return false;
    }
    return true;
}

void PlainShading::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    for (const SceneObject& original : scene.objects) {
        // GL draws a sphere map or a projected texture where the program generates them.
        const SceneObject& object = ShadingCommon::withGenerated(original, true, mGenerated);
        const bool textured = object.textured();
        const Variant& v = mVariants[textured ? 1 : 0];
        gl.UseProgram(v.program.id());
        v.u.set(gl, object);
        ShadingCommon::draw(ctx, object, v.u, textured);
    }
}

void PlainShading::shutdown(const GlFunctions& gl)
{
    for (Variant& v : mVariants) v.program.destroy(gl);
}

} // namespace nprgl::styles
