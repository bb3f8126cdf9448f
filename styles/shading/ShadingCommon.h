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
    // Sets the state drawTwoSided() needs (once per render()); returns whether the program's
    // front faces are counter-clockwise.
    static bool beginTwoSided(const GlFunctions& gl);
    // Draws the mesh's inward-facing triangles, then its outward-facing ones, both tested
    // against the scene's depth without writing it: where the polygon offset lets a far-side
    // triangle through at a silhouette, the near side drawn after it still wins.
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
