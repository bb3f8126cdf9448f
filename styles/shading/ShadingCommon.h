#pragma once

#include "common/Log.h"
#include "styles/Scene.h"
#include "styles/ShaderProgram.h"
#include "styles/StyleRegistry.h"
#include "styles/Style.h"

#include <glm/glm.hpp>

#include <string>

namespace nprgl::styles {

// What the chapter-3 shading styles share: one vertex shader and a few helpers.
//
// Their parameters are fixed for a chain's life, so each style bakes them into its fragment
// shader as constants and #if variants (llvmpipe runs both sides of uniform branches and
// pays for texture fetches it does not use); what changes per object is a variant (textured
// or not) and the uniforms below.
class ShadingCommon {
public:
    // Eye-space normal and position, the program's colour and texcoord, and `facing` for
    // shadingNormal().
    // Uniforms: see ObjectUniforms.
    static const char* vertexShader();
    // GLSL helper for fragment shaders: `vec3 shadingNormal(vec3 eyeNormal)` normalises and
    // flips it when it points away from the visible side (two-sided lighting), and
    // `float litDot(vec3 n, vec3 towardsLight)`, the light term: the sum over the first
    // `lights` of the object's SceneLights (0: towardsLight alone). Declares `in vec3
    // eyePosition`.
    static std::string normalFunction(int lights = 0);
    // A shading style's shader variants: [textured] + 2 * [lights class], the class by how
    // many lights the program lit the object with: none, one, two, or up to eight. Each sums
    // a fixed number of lights, so llvmpipe runs no loop of unknown length for any pixel (it
    // pays for every iteration the shader could run).
    static constexpr int kVariants = 8;
    static int variantIndex(bool textured, const SceneObject& object)
    {
        const uint32_t n = object.lights.count;
        return (textured ? 1 : 0) + 2 * (n == 0 ? 0 : n == 1 ? 1 : n == 2 ? 2 : 3);
    }
    // How many lights variant k's shader sums.
    static int variantLights(int k)
    {
        constexpr int kLights[4] = {0, 1, 2, 8};
        return kLights[(k / 2) & 3];
    }
    // The variant that draws `object`, built on first use by build(k, error) (a style's own
    // uniforms); where that fails, said once and the unlit variant instead.
    template <typename V, typename Build>
    static V& variantFor(V (&variants)[kVariants], uint32_t& failed, bool textured,
                         const SceneObject& object, Build&& build)
    {
        int k = variantIndex(textured, object);
        if (variants[k].program.id() == 0 && !(failed & (1u << k))) {
            std::string error;
            if (!build(k, error)) {
                failed |= 1u << k;
                NPRGL_ERROR("a shader for objects lit by %d light(s) does not build (%s); they "
                            "are shaded by a head-light",
                            variantLights(k), error.c_str());
            }
        }
        if (variants[k].program.id() == 0) k = textured ? 1 : 0;
        return variants[k];
    }
    // GLSL helper for fragment shaders: `vec3 programFog(vec3 colour, vec3 eyePosition)`, the
    // program's fog (SceneObject::fog) over a styled colour. Declare `in vec3 eyePosition`.
    static std::string fogFunction();
    // GLSL helper: `float fogFactor(float mode, float z, vec3 range)`, GL's fog factor at eye
    // distance z for fogModeCode(mode) and range (start, end, density), clamped to 0..1.
    static const char* fogFactorFunction();
    // GL_LINEAR, GL_EXP, GL_EXP2 as 1, 2, 3 for fogFactor(); 0 (no fog) for anything else.
    static float fogModeCode(GLenum mode);
    // The largest sum the shader's light term (litDot) reaches over all normals at eye-space
    // point `at`: each light's weight times its L.n, where positive, attenuated and spot-cut.
    static float brightestLitSum(const SceneLights& lights, glm::vec3 at);
    // The per-object uniforms of vertexShader(), plus the fragment shaders' lightDir and fog.
    struct ObjectUniforms {
        GLint modelview = -1, projection = -1, normalMatrix = -1, faceSign = -1, lightDir = -1;
        GLint fogMode = -1, fogRange = -1, fogColour = -1, layerScale = -1, layerOffset = -1;
        GLint lightmapped = -1, lightmapSampler = -1, flatLight = -1, ambientShare = -1, shine = -1;
        GLint diffuseShare = -1, twoSide = -1, shadowTint = -1;
        GLint lightPosition = -1, lightSpot = -1, lightFalloff = -1, lightWeight = -1;
        GLint genMode = -1, genPlaneS = -1, genPlaneT = -1, genMatrix = -1, normalScale = -1;
        GLint reflectionLight = -1;

        void find(const GlFunctions& gl, GLuint program);
        void set(const GlFunctions& gl, const SceneObject& object) const;
        // `at`: the object's origin in eye space, where positional lights are judged from.
        void setLights(const GlFunctions& gl, const SceneLights& lights, glm::vec3 at) const;
    };
    // Builds a variant's program (vertexShader() and `fragment`) and finds its ObjectUniforms;
    // false with the driver's log in error.
    static bool buildProgram(const GlFunctions& gl, ShaderProgram& program, ObjectUniforms& u,
                             const std::string& fragment, std::string& error);
    // Draws the object's faces with the program's textures bound on the active unit, run by
    // run (SceneObject::textureRuns); faces without one get a white texture, so that one
    // textured shader serves the whole object.
    // With a lightmap (SceneObject::lightmap, per run), it is bound on unit 3 and the shader's
    // litDot() takes the light from it.
    static void drawTextured(StyleContext& ctx, const SceneObject& object,
                             const ObjectUniforms& u);
    // The object's faces: through drawTextured when the style's variant samples textures or
    // the object has lightmaps, else in one draw.
    static void draw(StyleContext& ctx, const SceneObject& object, const ObjectUniforms& u,
                     bool textured);
    // The object as a style draws it: where it has no texture of its own but one on generated
    // coordinates (a linear projection, or a sphere-mapped reflection where `show`, the
    // style's reflectionsParam()), a copy in `scratch` with that as its texture, mapped on the
    // coordinates GL generates (ObjectUniforms::set).
    static const SceneObject& withGenerated(const SceneObject& object, bool show,
                                            SceneObject& scratch);
    static ParamInfo reflectionsParam();
    // Whether a sphere map the style drops is the object's light: the program did not light
    // it and it has no lightmap, so the reflection is the only shading GL shows on it.
    static bool reflectionLight(const SceneObject& object);
    // Whether the program's normals point out of the counter-clockwise side of its faces.
    static bool normalsFollowCcw(const reconstruct::ObjectMesh& mesh);
    static glm::mat3 normalMatrix(const glm::mat4& modelview);
    // GL_RESCALE_NORMAL's factor for a modelview: unit normals stay unit under its scale.
    static float rescaleFactor(const glm::mat4& modelview);
    // Where the object's origin lands, in window pixels: screen-space textures are anchored
    // there, so they follow the object when it moves across the screen instead of swimming.
    static glm::vec2 screenAnchor(const SceneObject& object, const glm::ivec4& viewport);
    // GLSL literals that read back as exactly these floats.
    static std::string glslFloat(float value);
    static std::string glslVec3(const glm::vec3& value);
    static std::string glslVec2(const glm::vec2& value);
};

} // namespace nprgl::styles
