#include "styles/shading/ShadingCommon.h"

#include <algorithm>


namespace nprgl::styles {

const char* ShadingCommon::vertexShader()
{
    return R"(#version 130
uniform mat4 modelview;
uniform mat4 projection;
uniform mat3 normalMatrix;
in vec3 position;
in vec3 normal;
in vec4 color;
in vec2 texcoord;
out vec3 eyeNormal;
out vec4 baseColor;
out vec2 uv;
out vec3 eyePos;
void main()
{
    eyeNormal = normalMatrix * normal;
    baseColor = color;
    uv = texcoord;
    vec4 eye = modelview * vec4(position, 1.0);
    eyePos = eye.xyz / eye.w;
    gl_Position = projection * eye;
}
)";
}

const char* ShadingCommon::normalFunction()
{
    return R"(
in vec3 eyePos;
vec3 shadingNormal(vec3 eyeNormal)
{
    vec3 n = normalize(eyeNormal);
    // The visible side of the triangle, from its screen-space derivatives: this does not
    // depend on the program's winding, which legacy programs often get backwards while
    // their normals are right. A normal pointing to the other side is flipped (two-sided).
    vec3 face = cross(dFdx(eyePos), dFdy(eyePos));
    return dot(n, face) < 0.0 ? -n : n;
}
)";
}

bool ShadingCommon::beginTwoSided(const GlFunctions& gl)
{
    GLint frontFace = GL_CCW;
    gl.GetIntegerv(GL_FRONT_FACE, &frontFace);
    return frontFace == GL_CCW;
}

void ShadingCommon::drawTwoSided(StyleContext& ctx, const reconstruct::ObjectMesh& mesh, bool)
{
    // One pass: the shading pass draws the held scene's depth itself (GL_LESS), so nearer
    // surfaces win whatever the order, and shadingNormal() lights both sides.
    ctx.meshes.draw(ctx.gl, mesh);
}

glm::mat3 ShadingCommon::normalMatrix(const glm::mat4& modelview)
{
    // The inverse transpose keeps normals perpendicular under non-uniform scaling.
    return glm::transpose(glm::inverse(glm::mat3(modelview)));
}

glm::vec2 ShadingCommon::screenAnchor(const SceneObject& object, const glm::ivec4& viewport)
{
    const glm::vec4 clip = object.projection * object.modelview * glm::vec4(0, 0, 0, 1);
    if (clip.w <= 1e-6f) return {float(viewport.x), float(viewport.y)};
    const glm::vec2 ndc = glm::vec2(clip) / clip.w;
    const glm::vec2 pixel = glm::vec2(viewport.x, viewport.y) +
                            (ndc * 0.5f + 0.5f) * glm::vec2(viewport.z, viewport.w);
    // Whole pixels: sub-pixel shifts would re-sample the pattern and shimmer.
    return glm::floor(pixel);
}

bool ShadingCommon::parseColor(const std::string& text, glm::vec3& out)
{
    // Hex, because the configuration separates its items with commas.
    const size_t skip = !text.empty() && text[0] == '#' ? 1 : 0;
    if (text.size() != skip + 6) return false;
    unsigned value = 0;
    for (size_t i = skip; i < text.size(); ++i) {
        const char c = text[i];
        const int digit = c >= '0' && c <= '9'   ? c - '0'
                          : c >= 'a' && c <= 'f' ? c - 'a' + 10
                          : c >= 'A' && c <= 'F' ? c - 'A' + 10
                                                 : -1;
        if (digit < 0) return false;
        value = value * 16 + unsigned(digit);
    }
    out = glm::vec3(float(value >> 16 & 0xff), float(value >> 8 & 0xff), float(value & 0xff)) /
          255.0f;
    return true;
}

} // namespace nprgl::styles
