#pragma once

#include "styles/ShaderProgram.h"
#include "styles/Style.h"
#include "styles/outlines/EdgeLines.h"
#include "styles/outlines/OutlineParams.h"

#include <glm/glm.hpp>

namespace nprgl::styles {

// Wireframe outlines (thesis §4.2, after Rossignac): the scene's depth is already in the
// depth buffer (a true two-pass), so back faces drawn as wide lines with front faces culled
// survive the depth test only as a halo around each object: its silhouette. Creases, borders
// and material edges come from the mesh's edge classes and are drawn as plain lines. Options:
// colour and width per class, antialiased lines, round points at vertices to fill the gaps
// between wide segments, the stencil to keep silhouette lines off the object's own visible
// surface, and HijackGL's depth cue (lines fade towards the background with distance).
class WireframeStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    struct LineClass {
        bool enabled = true;
        float width = 1.0f;
        InkClass ink;
    };
    // Order: silhouette, then EdgeLines::Kind + 1 (border, crease, material).
    enum { Silhouette = 0, ClassCount = 4 };

    void drawSilhouette(const SceneObject& object, StyleContext& ctx, uint8_t stencilId);
    void drawFeatureEdges(const SceneObject& object, StyleContext& ctx);
    void setClass(const StyleContext& ctx, const LineClass& c);
    void depthCueRange(const Scene& scene, StyleContext& ctx);

    ShaderProgram mProgram;
    EdgeLines mEdges;
    LineClass mClasses[ClassCount];
    bool mAntialias = false;
    bool mPoints = true;
    bool mStencil = false;
    float mDepthCue = 0.0f;
    float mPull = 0.0f;
    glm::vec2 mLineRange{1.0f}, mSmoothLineRange{1.0f}, mPointRange{1.0f};
    struct {
        GLint modelview = -1, projection = -1, pull = -1, inkColor = -1, fadeColor = -1,
              cueRange = -1, depthCue = -1, roundPoints = -1, pointSize = -1, smoothEdges = -1,
              normalMatrix = -1, featureEdge = -1, lineWidth = -1, pixelSize = -1,
              orthographic = -1, depthRange = -1;
    } mLoc;
};

} // namespace nprgl::styles
