#pragma once

#include "styles/ShaderProgram.h"
#include "styles/Style.h"
#include "styles/outlines/EdgeTargets.h"

#include <glm/glm.hpp>

namespace nprgl::styles {

// Image-space outlines (thesis §4.1.2 and §3.1.4): the whole scene is rendered off screen
// into view depth, eye normals and object ids/colours; an edge operator finds depth
// discontinuities (silhouettes), normal discontinuities (creases) and id or colour changes
// (material edges); a distance search widens each class to its width; the three layers are
// stacked like cels and composited over the framebuffer, depth-tested against the program's
// depth so that anything in front of an outline still hides it.
class EdgesStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    void drawFullscreen(const GlFunctions& gl);

    ShaderProgram mGeometry, mDetect, mDilate, mComposite;
    EdgeTargets mTargets;
    GLuint mTriangle = 0; // one triangle covering the viewport
    glm::vec3 mWidths{2.0f};
    glm::vec3 mColours[3];
    float mDepthThreshold = 0.05f;
    float mCreaseCosine = 0.6f;
    float mColourThreshold = 0.15f;
    int mRadius = 2;
    struct {
        GLint modelview = -1, projection = -1, normalMatrix = -1, objectId = -1,
              orthographic = -1, depthRange = -1;
    } mGeo;
    struct {
        GLint attributes = -1, normals = -1, depth = -1, size = -1, depthThreshold = -1,
              creaseCosine = -1, colourThreshold = -1;
    } mDet;
    struct {
        GLint edges = -1, size = -1, radius = -1;
    } mDil;
    struct {
        GLint dilated = -1, depth = -1, size = -1, origin = -1, radius = -1, widths = -1,
              colours = -1, depthBias = -1;
    } mCom;
};

} // namespace nprgl::styles
