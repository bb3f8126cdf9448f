#include "styles/shading/ShadingCommon.h"

#include "styles/FaceCulling.h"
#include "styles/ObjectNames.h"
#include "styles/textures/AbstractTextures.h"
#include "styles/textures/GlTexture.h"

#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>

namespace nprgl::styles {

// The normal GL lights by and reflects a sphere map about, for both shader stages: the
// program's as the modelview moved it, times normalScale (SceneObject::normals), or the unit
// normal where that is 0 (GL_NORMALIZE).
#define NPRGL_GL_NORMAL                                                                          \
    "uniform float normalScale;\n"                                                               \
    "vec3 glNormal(vec3 n) { return normalScale > 0.0 ? n * normalScale : normalize(n); }\n"

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
in vec2 lightcoord;
out vec3 eyeNormal;
out vec4 baseColor;
out vec2 uv;
out vec2 lightUv;
out vec3 eyePosition;
// The texture coordinates GL generates, per vertex as GL does (SceneObject::generated): for S
// and T, 0 the program's, 1 GL_SPHERE_MAP, 2 GL_OBJECT_LINEAR, 3 GL_EYE_LINEAR.
uniform vec2 genMode;
uniform vec4 genPlaneS;
uniform vec4 genPlaneT;
uniform mat4 genMatrix; // the unit's texture matrix, applied to generated coordinates
uniform float reflectionLight; // 1: the sphere map dropped is the light (reflectionLight())
// What the program's layers the styles do not draw multiply the colour by (SceneObject::
// layerScale), per vertex: it commutes with the texture's modulation.
uniform vec3 layerScale;
)" NPRGL_GL_NORMAL R"(
float generated(float mode, vec4 plane, float own, float sphere, vec4 eye)
{
    return mode < 0.5   ? own
           : mode < 1.5 ? sphere
           : mode < 2.5 ? dot(plane, vec4(position, 1.0))
                        : dot(plane, eye);
}
vec2 byGenMatrix(vec2 st) // generated coordinates moved by the unit's texture matrix
{
    vec4 moved = genMatrix * vec4(st, 0.0, 1.0);
    return moved.xy / (moved.w != 0.0 ? moved.w : 1.0);
}
void main()
{
    eyeNormal = normalMatrix * normal;
    baseColor = vec4(color.rgb * layerScale, color.a);
    lightUv = lightcoord;
    vec4 eye = modelview * vec4(position, 1.0);
    eyePosition = eye.xyz / eye.w;
    vec3 r = reflect(normalize(eyePosition), glNormal(eyeNormal));
    vec2 sphere = r.xy / max(2.0 * length(r + vec3(0.0, 0.0, 1.0)), 1e-6) + 0.5;
    if (reflectionLight > 0.5) lightUv = byGenMatrix(sphere); // the surface's light
    uv = vec2(generated(genMode.x, genPlaneS, texcoord.x, sphere.x, eye),
              generated(genMode.y, genPlaneT, texcoord.y, sphere.y, eye));
    if (genMode.x > 0.5) uv = byGenMatrix(uv); // the program's own came moved already
    gl_Position = projection * eye;
}
)";
}

std::string ShadingCommon::normalFunction(int lights)
{
    return "#define PROGRAM_LIGHTS " + std::to_string(lights) + R"(
uniform float faceSign;
vec3 shadingNormal(vec3 eyeNormal)
{
    vec3 n = normalize(eyeNormal);
    // Is the visible side the one the program's normals point out of? From the window-space
    // winding (gl_FrontFacing, by the styles' counter-clockwise front) and faceSign, which
    // folds in a mirroring modelview and which winding the mesh's normals follow (legacy
    // programs often wind backwards while their normals are right). The other side is lit
    // flipped.
    return gl_FrontFacing == (faceSign > 0.0) ? n : -n;
}

// The light a surface gets, as L·n in [-1, 1] (with `most`, up to that where a program's
// light attenuated by less than 1 brightens a near surface and its lights add up, as GL's
// do): from the program's lightmap where it has one and no GL lighting (its baked light's
// luminance); from the program's lights where it lit the object (SceneLights: each light's
// L·n at this point, attenuated and cut by its spot, weighted by brightness and summed as GL
// sums their diffuse light; where none reaches, the brightest light's own L·n, so the shadow
// side keeps its gradient); else from towardsLight.
uniform sampler2D lightmap;
uniform float lightmapped;
uniform float flatLight; // above -2: the light everywhere (SceneObject::flatLight)
uniform float ambientShare; // SceneLights::ambientShare of an object the program lit, else -1
uniform float diffuseShare; // SceneLights::diffuseShare (times the lights' peak), else -1
uniform vec3 shadowTint;    // SceneLights::shadowTint of an object the program lit, else 1
#if PROGRAM_LIGHTS
uniform vec4 lightPosition[PROGRAM_LIGHTS];
uniform vec4 lightSpot[PROGRAM_LIGHTS];    // where a spot points (unit); w: cos of its cutoff
uniform vec4 lightFalloff[PROGRAM_LIGHTS]; // constant, linear, quadratic attenuation; exponent
uniform float lightWeight[PROGRAM_LIGHTS]; // 0: no light (a variant sums more than there are)
#endif
in vec2 lightUv;
in vec3 eyePosition;
float litDot(vec3 n, vec3 towardsLight, float most)
{
    if (flatLight > -2.0) return flatLight;
    if (lightmapped > 0.5) {
        vec3 baked = texture(lightmap, lightUv).rgb;
        return 2.0 * dot(baked, vec3(0.299, 0.587, 0.114)) - 1.0;
    }
#if PROGRAM_LIGHTS
    // Without branches (llvmpipe runs both sides): a far light has attenuation 1, 0, 0 and a
    // light that is no spot a cutoff of -2 and exponent 0, so both factors are 1 there.
    float lit = 0.0;
    float key = 0.0;
    for (int i = 0; i < PROGRAM_LIGHTS; ++i) {
        vec4 p = lightPosition[i];
        vec3 l = p.xyz - eyePosition * p.w;
        float dist = length(l);
        l /= max(dist, 1e-6);
        vec4 f = lightFalloff[i];
        vec4 s = lightSpot[i];
        float c = dot(-l, s.xyz);
        float reach = step(s.w, c) * exp2(f.w * log2(max(c, 1e-4))) /
                      max(f.x + (f.y + f.z * dist) * dist, 1e-6);
        float d = dot(n, l) * min(reach, most);
        if (i == 0) key = d;
        lit += lightWeight[i] * max(d, 0.0);
    }
    return lit > 0.0 ? min(lit, most) : key;
#else
    return dot(n, towardsLight);
#endif
}
float litDot(vec3 n, vec3 towardsLight) { return litDot(n, towardsLight, 1.0); }

// The normal GL lights this point by: the program's as the modelview moved it (not unit
// unless GL_NORMALIZE: SceneObject::normals), turned on back faces with two-sided lighting
// (SceneLights::twoSide). Not shadingNormal(): GL lights a back face
// seen from behind by its front's normal, dark where the front faces away from the light.
// Back by the window winding, as GL tells them: the meshes keep the program's front
// counter-clockwise (MeshBuilder turns clockwise batches), drawn by the program's matrices.
uniform float twoSide;
)" NPRGL_GL_NORMAL R"(
vec3 programNormal(vec3 eyeNormal)
{
    vec3 n = glNormal(eyeNormal);
    return twoSide > 0.5 && !gl_FrontFacing ? -n : n;
}

// GL's specular term of the brightest light at this point (Blinn's half-vector, an infinite
// viewer), 0 where the material does not shine (SceneLights::shine; a: the exponent).
uniform vec4 shine;
float programShine(vec3 n)
{
#if PROGRAM_LIGHTS
    if (dot(shine.rgb, shine.rgb) <= 0.0) return 0.0;
    vec4 p = lightPosition[0];
    vec3 l = normalize(p.xyz - eyePosition * p.w);
    float nh = max(dot(n, normalize(l + vec3(0.0, 0.0, 1.0))), 0.0);
    return dot(n, l) > 0.0 ? pow(nh, max(shine.a, 1e-3)) : 0.0;
#else
    return 0.0;
#endif
}
)";
}

const char* ShadingCommon::fogFactorFunction()
{
    return R"(
float fogFactor(float mode, float z, vec3 range)
{
    float d = range.z * z;
    float f = mode < 0.5   ? 1.0
              : mode < 1.5 ? (range.y - z) / max(range.y - range.x, 1e-6)
              : mode < 2.5 ? exp(-d)
                           : exp(-d * d);
    return clamp(f, 0.0, 1.0);
}
)";
}

std::string ShadingCommon::fogFunction()
{
    return std::string(fogFactorFunction()) + R"(
uniform float fogMode;  // fogModeCode()
uniform vec3 fogRange;  // start, end, density
uniform vec3 fogColour;
uniform vec3 layerOffset; // SceneObject::layerOffset (the layers' scale is the vertices')
// What GL does after the surface's texture: the layers the styles do not draw (on average),
// then fog.
vec3 programFog(vec3 colour, vec3 eyePosition)
{
    colour += layerOffset;
    // GL's fog coordinate: the eye-space depth.
    return mix(fogColour, colour, fogFactor(fogMode, abs(eyePosition.z), fogRange));
}
)";
}

float ShadingCommon::fogModeCode(GLenum mode)
{
    return mode == GL_LINEAR ? 1.0f : mode == GL_EXP ? 2.0f : mode == GL_EXP2 ? 3.0f : 0.0f;
}

void ShadingCommon::ObjectUniforms::find(const GlFunctions& gl, GLuint program)
{
    fogMode = gl.GetUniformLocation(program, "fogMode");
    fogRange = gl.GetUniformLocation(program, "fogRange");
    fogColour = gl.GetUniformLocation(program, "fogColour");
    layerScale = gl.GetUniformLocation(program, "layerScale");
    layerOffset = gl.GetUniformLocation(program, "layerOffset");
    modelview = gl.GetUniformLocation(program, "modelview");
    projection = gl.GetUniformLocation(program, "projection");
    normalMatrix = gl.GetUniformLocation(program, "normalMatrix");
    faceSign = gl.GetUniformLocation(program, "faceSign");
    lightDir = gl.GetUniformLocation(program, "lightDir");
    lightmapped = gl.GetUniformLocation(program, "lightmapped");
    lightmapSampler = gl.GetUniformLocation(program, "lightmap");
    flatLight = gl.GetUniformLocation(program, "flatLight");
    ambientShare = gl.GetUniformLocation(program, "ambientShare");
    shine = gl.GetUniformLocation(program, "shine");
    diffuseShare = gl.GetUniformLocation(program, "diffuseShare");
    shadowTint = gl.GetUniformLocation(program, "shadowTint");
    twoSide = gl.GetUniformLocation(program, "twoSide");
    lightPosition = gl.GetUniformLocation(program, "lightPosition");
    lightSpot = gl.GetUniformLocation(program, "lightSpot");
    lightFalloff = gl.GetUniformLocation(program, "lightFalloff");
    lightWeight = gl.GetUniformLocation(program, "lightWeight");
    genMode = gl.GetUniformLocation(program, "genMode");
    genPlaneS = gl.GetUniformLocation(program, "genPlaneS");
    genPlaneT = gl.GetUniformLocation(program, "genPlaneT");
    genMatrix = gl.GetUniformLocation(program, "genMatrix");
    normalScale = gl.GetUniformLocation(program, "normalScale");
    reflectionLight = gl.GetUniformLocation(program, "reflectionLight");
}

bool ShadingCommon::buildProgram(const GlFunctions& gl, ShaderProgram& program,
                                 ObjectUniforms& u, const std::string& fragment,
                                 std::string& error)
{
    if (!program.build(gl, vertexShader(), fragment.c_str(), error)) return false;
    u.find(gl, program.id());
    return true;
}

bool ShadingCommon::normalsFollowCcw(const reconstruct::ObjectMesh& mesh)
{
    // A sample of faces is enough: meshes are consistent or not at all.
    const uint32_t faces = mesh.faceCount();
    const uint32_t step = std::max(1u, faces / 64);
    int agree = 0;
    for (uint32_t f = 0; f < faces; f += step) {
        const reconstruct::Vertex& c = mesh.corner(f, 0);
        const glm::vec3 n = c.hasNormal ? c.normal : mesh.vertexNormal(mesh.faceVertices[3 * f]);
        const float d = glm::dot(mesh.faceNormal(f), n); // faceNormal follows CCW winding
        agree += d > 0.0f ? 1 : d < 0.0f ? -1 : 0;
    }
    return agree >= 0;
}

void ShadingCommon::ObjectUniforms::set(const GlFunctions& gl, const SceneObject& object) const
{
    gl.UniformMatrix4fv(modelview, 1, GL_FALSE, glm::value_ptr(object.modelview));
    gl.UniformMatrix4fv(projection, 1, GL_FALSE, glm::value_ptr(object.projection));
    const glm::mat3 normals = ShadingCommon::normalMatrix(object.modelview);
    gl.UniformMatrix3fv(normalMatrix, 1, GL_FALSE, glm::value_ptr(normals));
    // gl_FrontFacing is by the styles' counter-clockwise front (StyleChain's baseline). A
    // mirroring modelview or projection turns the faces' winding around, and so do normals
    // that follow the clockwise side.
    const bool flip = object.mirrored() ^ !normalsFollowCcw(*object.mesh);
    gl.Uniform1f(faceSign, flip ? -1.0f : 1.0f);
    gl.Uniform3fv(lightDir, 1, glm::value_ptr(object.lightDir));
    setLights(gl, object.lights, glm::vec3(object.modelview[3]));
    // The generated coordinates where the object shows its generated texture as its own
    // (withGenerated), else the program's.
    const GeneratedTexture& g = object.generated;
    const bool generates = g.texture != 0 && object.texture == g.texture;
    auto code = [&](GLenum mode) {
        return !generates                ? 0.0f
               : mode == GL_SPHERE_MAP   ? 1.0f
               : mode == GL_OBJECT_LINEAR ? 2.0f
                                         : 3.0f;
    };
    gl.Uniform2f(genMode, code(g.mode[0]), code(g.mode[1]));
    gl.Uniform4fv(genPlaneS, 1, glm::value_ptr(g.plane[0]));
    gl.Uniform4fv(genPlaneT, 1, glm::value_ptr(g.plane[1]));
    gl.UniformMatrix4fv(genMatrix, 1, GL_FALSE, glm::value_ptr(g.matrix));
    const bool reflectedLight = object.lightmap != 0 && object.lightmap == g.texture &&
                                !generates && object.lights.count == 0 && !object.flatLight;
    gl.Uniform1f(reflectionLight, reflectedLight ? 1.0f : 0.0f);
    gl.Uniform1f(normalScale, object.normals == GL_NORMALIZE ? 0.0f
                              : object.normals == GL_RESCALE_NORMAL
                                  ? rescaleFactor(object.modelview)
                                  : 1.0f);
    // Between the toon bands' thresholds (their base colour), halftone's light dots.
    gl.Uniform1f(flatLight, object.flatLight ? 0.5f : -2.0f);
    const bool lit = object.lights.count > 0 && !object.flatLight;
    gl.Uniform1f(ambientShare, lit ? object.lights.ambientShare : -1.0f);
    const glm::vec3 tint = lit ? object.lights.shadowTint : glm::vec3(1.0f);
    gl.Uniform3fv(shadowTint, 1, glm::value_ptr(tint));
    const glm::vec4 shines(lit ? object.lights.shine : glm::vec3(0.0f), object.lights.shininess);
    gl.Uniform4fv(shine, 1, glm::value_ptr(shines));
    gl.Uniform1i(lightmapSampler, 3);
    gl.Uniform1f(lightmapped, 0.0f); // drawTextured says where a lightmap is bound
    // A generated texture the styles drop keeps its average tint (GeneratedTexture::mean).
    const glm::vec3 scale =
        g.texture != 0 && !generates ? object.layerScale * g.mean : object.layerScale;
    gl.Uniform3fv(layerScale, 1, glm::value_ptr(scale));
    if (fogMode >= 0) {
        const SceneObject::Fog& f = object.fog;
        gl.Uniform1f(fogMode, fogModeCode(f.mode));
        gl.Uniform3f(fogRange, f.start, f.end, f.density);
        gl.Uniform3fv(fogColour, 1, glm::value_ptr(f.colour));
        gl.Uniform3fv(layerOffset, 1, glm::value_ptr(object.layerOffset));
    }
}

float ShadingCommon::brightestLitSum(const SceneLights& lights, glm::vec3 at)
{
    // Each light as the shader takes it at `at`: towards it, weighted, attenuated, cut by its
    // spot. The sum of w max(n.l, 0) is largest at the normal along the sum of the lights it
    // faces: every set of lights' sum direction is tried (at most 255 for 8 lights).
    const uint32_t n = std::min<uint32_t>(lights.count, 8);
    glm::vec3 towards[8];
    for (uint32_t i = 0; i < n; ++i) {
        const SceneLights::Light& l = lights.lights[i];
        glm::vec3 d = glm::vec3(l.position) - at * l.position.w;
        const float dist = glm::length(d);
        d /= std::max(dist, 1e-6f);
        const float c = glm::dot(-d, l.spotDirection);
        const float spot = c < l.spotCosCutoff ? 0.0f
                                               : std::pow(std::max(c, 1e-4f), l.falloff.w);
        const glm::vec4& f = l.falloff;
        const float reach = spot / std::max(f.x + (f.y + f.z * dist) * dist, 1e-6f);
        towards[i] = d * (std::max(l.weight, 0.0f) * std::min(reach, 1.0f));
    }
    float best = 0.0f;
    for (uint32_t set = 1; set < (1u << n); ++set) {
        glm::vec3 sum(0.0f);
        for (uint32_t i = 0; i < n; ++i) {
            if (set & (1u << i)) sum += towards[i];
        }
        const float length = glm::length(sum);
        if (!(length > 1e-6f)) continue;
        const glm::vec3 normal = sum / length;
        float lit = 0.0f;
        for (uint32_t i = 0; i < n; ++i) lit += std::max(glm::dot(normal, towards[i]), 0.0f);
        best = std::max(best, lit);
    }
    return best;
}

void ShadingCommon::ObjectUniforms::setLights(const GlFunctions& gl, const SceneLights& lights,
                                              glm::vec3 at) const
{
    if (lightPosition < 0) return; // a variant without the program's lights
    // The shader sums all 8 in its largest variant: the ones past the object's weigh nothing.
    // The lights come as the shader takes them (StateTracker::litBy).
    glm::vec4 position[8], spot[8], falloff[8];
    float weight[8];
    const uint32_t n = std::min<uint32_t>(lights.count, 8);
    // Lit 1 where GL lights the object most: two lights of about one strength from nearby
    // directions (pymol's head-light and its second light) sum to nearly 2 over most of a
    // surface, all of it then in the highlight band, pale, where GL shows the material's
    // own colour. One light, or lights that never shine on one face together, change nothing.
    const float peak = std::max(brightestLitSum(lights, at), 1.0f);
    for (uint32_t i = 0; i < 8; ++i) {
        SceneLights::Light l;
        if (i < n) l = lights.lights[i];
        else l.weight = 0.0f;
        position[i] = l.position;
        spot[i] = glm::vec4(l.spotDirection, l.spotCosCutoff);
        falloff[i] = l.falloff;
        weight[i] = l.weight / peak;
    }
    gl.Uniform4fv(lightPosition, 8, glm::value_ptr(position[0]));
    gl.Uniform4fv(lightSpot, 8, glm::value_ptr(spot[0]));
    gl.Uniform4fv(lightFalloff, 8, glm::value_ptr(falloff[0]));
    gl.Uniform1fv(lightWeight, 8, weight);
    // litDot() sums the weights over the peak: GL's own light is the key light's share times
    // the peak times that.
    gl.Uniform1f(diffuseShare, lights.diffuseShare >= 0.0f ? lights.diffuseShare * peak : -1.0f);
    gl.Uniform1f(twoSide, lights.twoSide ? 1.0f : 0.0f);
}

const SceneObject& ShadingCommon::withGenerated(const SceneObject& object, bool show,
                                               SceneObject& scratch)
{
    // A projection on linear planes (terrain textured by GL_OBJECT_LINEAR) is the surface's
    // own texture; a sphere map reflects the surroundings, only shown when asked.
    const GeneratedTexture& g = object.generated;
    const bool reflects = g.mode[0] == GL_SPHERE_MAP || g.mode[1] == GL_SPHERE_MAP;
    if (g.texture == 0 || object.textured()) return object;
    if (reflects && !show) {
        // Without GL lighting the reflection is all the light the program's picture shows
        // (blocktube's blocks): it gives the styles their light, as a lightmap does, on the
        // coordinates GL generates (reflectionLight).
        if (!reflectionLight(object)) return object;
        scratch = object;
        scratch.lightmap = g.texture;
        return scratch;
    }
    scratch = object;
    scratch.texture = object.generated.texture;
    scratch.textureRuns.clear();
    return scratch;
}

bool ShadingCommon::reflectionLight(const SceneObject& object)
{
    const GeneratedTexture& g = object.generated;
    const bool reflects = g.mode[0] == GL_SPHERE_MAP && g.mode[1] == GL_SPHERE_MAP;
    return reflects && g.texture != 0 && object.texture != g.texture &&
           object.lights.count == 0 && !object.flatLight && !object.lightmapped();
}

ParamInfo ShadingCommon::reflectionsParam()
{
    return ParamInfo::flag("reflections",
                           "a texture the program maps by GL_SPHERE_MAP coordinates (chrome, "
                           "reflections) shown as the object's texture (off: dropped; one on "
                           "GL_OBJECT_LINEAR or GL_EYE_LINEAR planes is always the surface's; "
                           "dropped from a surface GL does not light, it is the light)",
                           false);
}

float ShadingCommon::rescaleFactor(const glm::mat4& modelview)
{
    // GL_RESCALE_NORMAL's f: one over the length of the inverse's third row.
    const glm::mat3 inverse = glm::inverse(glm::mat3(modelview));
    const float length = glm::length(glm::vec3(inverse[0][2], inverse[1][2], inverse[2][2]));
    return length > 0.0f && std::isfinite(length) ? 1.0f / length : 1.0f;
}

glm::mat3 ShadingCommon::normalMatrix(const glm::mat4& modelview)
{
    // The inverse transpose keeps normals perpendicular under non-uniform scaling.
    return glm::transpose(glm::inverse(glm::mat3(modelview)));
}

namespace {

// Binds the program's texture for the styles. A GL_ALPHA texture has no colour: the fixed
// pipeline keeps the fragment's (modulating only its alpha), but a shader samples it black,
// so text and sprites drawn with one vanished. While the styles draw with it its colour
// channels read one (texture swizzle); unbindProgramTexture puts the program's back.
// A 1x1 white texture, made on first use: the textured shader then shows the faces' own
// colours.
GLuint blankTexture(StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    if (!ctx.blankTexture) {
        GlTexture::resetUnpack(gl);
        ObjectNames::reserve(gl, ObjectNames::Kind::Texture, 1, &ctx.blankTexture);
        gl.BindTexture(GL_TEXTURE_2D, ctx.blankTexture);
        const uint8_t white[4] = {255, 255, 255, 255};
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, white);
    }
    return ctx.blankTexture;
}

bool bindProgramTexture(StyleContext& ctx, GLuint texture, GLint (&swizzle)[4])
{
    const GlFunctions& gl = ctx.gl;
    gl.BindTexture(GL_TEXTURE_2D, textureName(texture));
    if (texture == 0) return false;
    // A texture the program bound but never gave an image is incomplete: GL draws as if its
    // unit were off (atunnel's lit tunnel), where sampling it would give black.
    GLint width = 0;
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH, &width);
    if (width == 0) {
        gl.BindTexture(GL_TEXTURE_2D, blankTexture(ctx));
        return false;
    }
    GLint format = 0;
    gl.GetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
    if (format != GL_ALPHA && format != GL_ALPHA4 && format != GL_ALPHA8 &&
        format != GL_ALPHA12 && format != GL_ALPHA16) {
        // Drawn as a drawing where the style asks for it (the abstraction binds itself).
        if (ctx.abstractions && ctx.textureDetail < 1.0f) {
            const uint64_t content = ctx.textureContent ? ctx.textureContent(texture) : 0;
            ctx.abstractions->substitute(gl, textureName(texture), content, ctx.textureDetail,
                                         ctx.frame);
        }
        return false;
    }
    gl.GetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
    const GLint ones[4] = {GL_ONE, GL_ONE, GL_ONE, swizzle[3]};
    gl.TexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, ones);
    return true;
}

void unbindProgramTexture(const GlFunctions& gl, bool swizzled, const GLint (&swizzle)[4])
{
    if (swizzled) gl.TexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_SWIZZLE_RGBA, swizzle);
}

} // namespace

void ShadingCommon::drawTextured(StyleContext& ctx, const SceneObject& object,
                                 const ObjectUniforms& u)
{
    const GlFunctions& gl = ctx.gl;
    // The lightmap on unit 3 (0 holds the surface's texture, 1 and 2 the styles' own).
    auto useLightmap = [&](GLuint lightmap) {
        gl.Uniform1f(u.lightmapped, lightmap != 0 ? 1.0f : 0.0f);
        if (lightmap == 0) return;
        gl.ActiveTexture(GL_TEXTURE3);
        gl.BindTexture(GL_TEXTURE_2D, textureName(lightmap));
        gl.ActiveTexture(GL_TEXTURE0);
    };
    if (object.textureRuns.empty()) {
        useLightmap(object.lightmap);
        GLint swizzle[4];
        const bool swizzled = bindProgramTexture(ctx, object.texture, swizzle);
        ctx.meshes.draw(gl, *object.mesh);
        unbindProgramTexture(gl, swizzled, swizzle);
        return;
    }
    for (const SceneObject::TextureRun& run : object.textureRuns) {
        GLuint texture = run.texture;
        if (texture == 0) texture = blankTexture(ctx);
        useLightmap(run.lightmap);
        GLint swizzle[4];
        const bool swizzled = bindProgramTexture(ctx, texture, swizzle);
        ctx.meshes.drawFaces(gl, *object.mesh, run.firstFace, run.faceCount);
        unbindProgramTexture(gl, swizzled, swizzle);
    }
}

void ShadingCommon::draw(StyleContext& ctx, const SceneObject& object, const ObjectUniforms& u,
                         bool textured)
{
    if (!FaceCulling::begin(ctx.gl, object)) return;
    if (textured || object.lightmapped()) {
        drawTextured(ctx, object, u);
    } else {
        ctx.meshes.draw(ctx.gl, *object.mesh);
    }
    FaceCulling::end(ctx.gl, object);
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

std::string ShadingCommon::glslFloat(float value)
{
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", double(value));
    // A bare integer would be an int literal.
    if (!std::strpbrk(text, ".e")) std::strcat(text, ".0");
    return text;
}

std::string ShadingCommon::glslVec3(const glm::vec3& value)
{
    return "vec3(" + glslFloat(value.x) + ", " + glslFloat(value.y) + ", " + glslFloat(value.z) +
           ")";
}

std::string ShadingCommon::glslVec2(const glm::vec2& value)
{
    return "vec2(" + glslFloat(value.x) + ", " + glslFloat(value.y) + ")";
}

} // namespace nprgl::styles
