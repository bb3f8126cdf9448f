#include "styles/shading/ToonStyle.h"

#include "styles/StyleRegistry.h"

#include <glm/gtc/type_ptr.hpp>

namespace nprgl::styles {

namespace {

const char* kVertex = R"(#version 130
uniform mat4 modelview;
uniform mat4 projection;
in vec3 position;
in vec3 normal;
in vec4 color;
in vec2 texcoord;
out vec3 eyeNormal;
out vec4 baseColor;
void main()
{
    eyeNormal = mat3(modelview) * normal;
    baseColor = color;
    gl_Position = projection * (modelview * vec4(position, 1.0));
}
)";

const char* kFragment = R"(#version 130
uniform vec3 lightDir;
uniform float diffuseThreshold;
uniform float highlightThreshold;
uniform float shadowScale;
uniform float highlightMix;
uniform int tones;
in vec3 eyeNormal;
in vec4 baseColor;
out vec4 fragColor;
void main()
{
    vec3 n = normalize(eyeNormal);
    if (!gl_FrontFacing) n = -n;
    float d = dot(n, lightDir);
    vec3 c = baseColor.rgb;
    if (d < diffuseThreshold) c *= shadowScale;
    else if (tones == 3 && d > highlightThreshold) c = mix(c, vec3(1.0), highlightMix);
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
        ParamInfo::number("highlight_threshold", "t_h: L.n above it is highlight", 0.92, -1.0,
                          1.0),
        ParamInfo::number("shadow_scale", "shadow colour = base colour x this", 0.55, 0.0, 1.0),
        ParamInfo::number("highlight_mix", "highlight colour = base mixed with white by this",
                          0.55, 0.0, 1.0),
    };
    return info;
}

bool ToonStyle::init(StyleContext& ctx, std::string& error)
{
    return mProgram.build(ctx.gl, kVertex, kFragment, error);
}

void ToonStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    gl.UseProgram(mProgram.id());
    gl.Uniform1f(mProgram.uniform(gl, "diffuseThreshold"), float(ctx.param("toon", "diffuse_threshold")));
    gl.Uniform1f(mProgram.uniform(gl, "highlightThreshold"), float(ctx.param("toon", "highlight_threshold")));
    gl.Uniform1f(mProgram.uniform(gl, "shadowScale"), float(ctx.param("toon", "shadow_scale")));
    gl.Uniform1f(mProgram.uniform(gl, "highlightMix"), float(ctx.param("toon", "highlight_mix")));
    gl.Uniform1i(mProgram.uniform(gl, "tones"), int(ctx.param("toon", "tones")));
    for (const SceneObject& object : scene.objects) {
        gl.UniformMatrix4fv(mProgram.uniform(gl, "modelview"), 1, GL_FALSE,
                            glm::value_ptr(object.modelview));
        gl.UniformMatrix4fv(mProgram.uniform(gl, "projection"), 1, GL_FALSE,
                            glm::value_ptr(object.projection));
        gl.Uniform3fv(mProgram.uniform(gl, "lightDir"), 1, glm::value_ptr(object.lightDir));
        ctx.meshes.draw(gl, *object.mesh);
    }
}

void ToonStyle::shutdown(StyleContext& ctx) { mProgram.destroy(ctx.gl); }

} // namespace nprgl::styles
