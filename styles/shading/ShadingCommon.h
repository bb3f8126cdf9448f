#pragma once

#include "styles/Scene.h"
#include "styles/Style.h"

#include <glm/glm.hpp>

#include <string>

namespace nprgl::styles {

// What the chapter-3 shading styles share: one vertex shader and a few helpers.
class ShadingCommon {
public:
    // Eye-space normal, the program's colour and texcoord, and the eye position. Uniforms:
    // mat4 modelview, mat4 projection, mat3 normalMatrix (see normalMatrix()).
    static const char* vertexShader();
    // GLSL helper for fragment shaders: `vec3 shadingNormal(vec3 eyeNormal)` normalises and
    // flips it when it points away from the visible side (two-sided lighting).
    static const char* normalFunction();
    // Returns whether the program's front faces are counter-clockwise (once per render()).
    static bool beginTwoSided(const GlFunctions& gl);
    // Draws the mesh, both sides, in one pass with depth writes (the shading baseline).
    static void drawTwoSided(StyleContext& ctx, const reconstruct::ObjectMesh& mesh,
                             bool frontIsCcw);
    static glm::mat3 normalMatrix(const glm::mat4& modelview);
    // Where the object's origin lands, in window pixels: screen-space textures are anchored
    // there, so they follow the object when it moves across the screen instead of swimming.
    static glm::vec2 screenAnchor(const SceneObject& object, const glm::ivec4& viewport);
    // "rrggbb" or "#rrggbb" (hex) into a colour; false when empty or malformed.
    static bool parseColor(const std::string& text, glm::vec3& out);
};

} // namespace nprgl::styles
