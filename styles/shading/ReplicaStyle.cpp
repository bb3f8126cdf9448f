#include "styles/shading/ReplicaStyle.h"

#include "styles/StyleRegistry.h"

namespace nprgl::styles {

namespace {

// GL's texture environment GL_MODULATE on the surface and the lightmap unit, then the layers
// not drawn and fog (programFog). A GL_REPLACE texture's colours came white from the tracker.
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
    if (lightmapped > 0.5) c.rgb *= texture(lightmap, lightUv).rgb;
    fragColor = vec4(programFog(c.rgb, eyePosition), c.a);
}
)";

std::unique_ptr<Style> create() { return std::make_unique<ReplicaStyle>(); }

} // namespace

StyleInfo replicaStyleInfo()
{
    StyleInfo info;
    info.name = "replica";
    info.summary = "the scene as GL draws it, from what nprgl tracked (no NPR): the oracle "
                   "`nprgl compare` measures against the program's own frames";
    info.role = StyleRole::Shading;
    info.programLighting = true;
    info.create = &create;
    return info;
}

bool ReplicaStyle::init(StyleContext& ctx, std::string& error)
{
    for (int textured = 0; textured < 2; ++textured) {
        const std::string fragment = "#version 130\n#define TEXTURED " +
                                     std::to_string(textured) + "\n" +
                                     ShadingCommon::fogFunction() + kFragment;
        Variant& v = mVariants[textured];
        if (!ShadingCommon::buildProgram(ctx.gl, v.program, v.u, fragment, error)) return false;
    }
    return true;
}

void ReplicaStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    for (const SceneObject& original : scene.objects) {
        // GL draws a sphere map or a projected texture where the program generates them.
        const SceneObject& object = ShadingCommon::withGenerated(original, true, mReflected);
        const bool textured = object.textured();
        const Variant& v = mVariants[textured ? 1 : 0];
        gl.UseProgram(v.program.id());
        v.u.set(gl, object);
        ShadingCommon::draw(ctx, object, v.u, textured);
    }
}

void ReplicaStyle::shutdown(StyleContext& ctx)
{
    for (Variant& v : mVariants) v.program.destroy(ctx.gl);
}

} // namespace nprgl::styles
