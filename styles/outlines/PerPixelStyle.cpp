#include "styles/outlines/PerPixelStyle.h"

#include "styles/FaceCulling.h"
#include "styles/StyleRegistry.h"
#include "styles/outlines/OutlineParams.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

namespace nprgl::styles {

namespace {

constexpr const char* kStyle = "perpixel";

const char* kVertex = R"(#version 130
uniform mat4 modelview;
uniform mat4 projection;
uniform mat3 normalMatrix;
in vec3 position;
in vec3 normal;
out vec3 eyePosition;
out vec3 eyeNormal;
void main()
{
    vec4 eye = modelview * vec4(position, 1.0);
    eyePosition = eye.xyz / eye.w;
    eyeNormal = normalMatrix * normal;
    gl_Position = projection * eye;
}
)";

// In eye space the eye is the origin, so (v − P)·n is dot(-P, n); normalising −P makes ε a
// cosine, independent of the distance. An orthographic view looks along −z everywhere.
const char* kFragment = R"(#version 130
uniform bool orthographic;
uniform float epsilon;
uniform vec3 inkColor;
uniform bool smoothEdges;
in vec3 eyePosition;
in vec3 eyeNormal;
out vec4 fragColor;
void main()
{
    vec3 n = normalize(eyeNormal);
    vec3 toEye = orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-eyePosition);
    // Seen from the side the program's normals point away from (the inside of an open part,
    // or any face where normals and winding disagree: a mirrored half drawn with a clockwise
    // front), the surface is judged by its other side. Which side is seen comes from the
    // face's own plane, not from its winding: programs wind their parts either way.
    vec3 face = cross(dFdx(eyePosition), dFdy(eyePosition));
    if (dot(face, toEye) * dot(face, n) < 0.0) n = -n;
    float d = dot(toEye, n);
    float alpha = d < epsilon ? 1.0 : 0.0;
    if (smoothEdges) {
        // Half a pixel's change of d either side of the threshold.
        float w = 0.5 * fwidth(d);
        alpha = 1.0 - smoothstep(epsilon - w, epsilon + w, d);
    }
    if (alpha <= 0.0) discard;
    fragColor = vec4(inkColor, alpha);
}
)";

std::unique_ptr<Style> create() { return std::make_unique<PerPixelStyle>(); }

} // namespace

StyleInfo perpixelStyleInfo()
{
    StyleInfo info;
    info.name = kStyle;
    info.summary = "per-pixel outlines: ink where the surface turns away from the eye, "
                   "(v-P).n < epsilon (thesis 4.3)";
    info.role = StyleRole::Outline;
    info.create = &create;
    auto& p = info.params;
    p.push_back(ParamInfo::number(
        "epsilon",
        "threshold on the cosine between the unit normal and the direction to the eye; "
        "larger values draw wider outlines",
        0.25, 0.0, 1.0));
    addInkParams(p);
    p.push_back(ParamInfo::flag("antialias", "blend the outline's inner boundary over a pixel",
                                true));
    return info;
}

bool PerPixelStyle::init(StyleContext& ctx, std::string& error)
{
    const GlFunctions& gl = ctx.gl;
    if (!mProgram.build(gl, kVertex, kFragment, error)) return false;
    mLoc.modelview = mProgram.uniform(gl, "modelview");
    mLoc.projection = mProgram.uniform(gl, "projection");
    mLoc.normalMatrix = mProgram.uniform(gl, "normalMatrix");
    mLoc.orthographic = mProgram.uniform(gl, "orthographic");
    mLoc.epsilon = mProgram.uniform(gl, "epsilon");
    mLoc.inkColor = mProgram.uniform(gl, "inkColor");
    mLoc.smoothEdges = mProgram.uniform(gl, "smoothEdges");
    mEpsilon = float(ctx.param(kStyle, "epsilon"));
    mAntialias = ctx.param(kStyle, "antialias") != 0.0;
    mInk = inkColour(ctx, kStyle);
    return true;
}

void PerPixelStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    gl.UseProgram(mProgram.id());
    gl.Uniform1f(mLoc.epsilon, mEpsilon);
    const glm::vec3 ink = ctx.page.ink(mInk);
    gl.Uniform3fv(mLoc.inkColor, 1, glm::value_ptr(ink));
    gl.Uniform1i(mLoc.smoothEdges, mAntialias ? 1 : 0);
    // Over the surfaces already there: the baseline's LEQUAL and polygon offset let each
    // surface win against its own depth; the ink needs no depth of its own.
    gl.DepthMask(GL_FALSE);
    if (mAntialias) {
        gl.Enable(GL_BLEND);
        gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    }
    for (const SceneObject& o : scene.objects) {
        const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(o.modelview));
        const bool ortho = o.orthographic();
        gl.UniformMatrix4fv(mLoc.modelview, 1, GL_FALSE, glm::value_ptr(o.modelview));
        gl.UniformMatrix4fv(mLoc.projection, 1, GL_FALSE, glm::value_ptr(o.projection));
        gl.UniformMatrix3fv(mLoc.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
        gl.Uniform1i(mLoc.orthographic, ortho ? 1 : 0);
        // What the program culls is not on screen: no ink on it.
        if (!FaceCulling::begin(gl, o)) continue;
        ctx.meshes.draw(gl, *o.mesh);
        FaceCulling::end(gl, o);
    }
}

void PerPixelStyle::shutdown(StyleContext& ctx) { mProgram.destroy(ctx.gl); }

} // namespace nprgl::styles
