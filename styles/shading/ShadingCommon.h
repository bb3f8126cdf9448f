#pragma once

#include "styles/Scene.h"
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
    // `float litDot(vec3 n, vec3 towardsLight)`, the light term. Declares `in vec3
    // eyePosition`.
    static const char* normalFunction();
    // GLSL helper for fragment shaders: `vec3 programFog(vec3 colour, vec3 eyePosition)`, the
    // program's fog (SceneObject::fog) over a styled colour. Declare `in vec3 eyePosition`.
    static const char* fogFunction();
    // The per-object uniforms of vertexShader(), plus the fragment shaders' lightDir and fog.
    struct ObjectUniforms {
        GLint modelview = -1, projection = -1, normalMatrix = -1, faceSign = -1, lightDir = -1;
        GLint fogMode = -1, fogRange = -1, fogColour = -1;
        GLint lightmapped = -1, lightmapSampler = -1;
        GLint lightCount = -1, lightPosition = -1, lightSpot = -1, lightFalloff = -1,
              lightWeight = -1;

        void find(const GlFunctions& gl, GLuint program);
        void set(const GlFunctions& gl, const SceneObject& object, bool frontIsCcw) const;
        void setLights(const GlFunctions& gl, const SceneLights& lights) const;
    };
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
    // Returns whether the program's front faces are counter-clockwise (once per render()).
    static bool beginTwoSided(const GlFunctions& gl);
    // Whether the program's normals point out of the counter-clockwise side of its faces.
    static bool normalsFollowCcw(const reconstruct::ObjectMesh& mesh);
    static glm::mat3 normalMatrix(const glm::mat4& modelview);
    // Where the object's origin lands, in window pixels: screen-space textures are anchored
    // there, so they follow the object when it moves across the screen instead of swimming.
    static glm::vec2 screenAnchor(const SceneObject& object, const glm::ivec4& viewport);
    // GLSL literals that read back as exactly these floats.
    static std::string glslFloat(float value);
    static std::string glslVec3(const glm::vec3& value);
    static std::string glslVec2(const glm::vec2& value);
};

} // namespace nprgl::styles
