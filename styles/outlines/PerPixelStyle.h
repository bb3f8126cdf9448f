#pragma once

#include "styles/ShaderProgram.h"
#include "styles/Style.h"

#include <glm/glm.hpp>

namespace nprgl::styles {

// Per-pixel outlines (thesis §4.3): a surface point P with unit normal n is on the outline
// when (v − P)·n < ε for the eye v, i.e. where the surface turns away from the view. The
// test runs per pixel over the already drawn surfaces (depth test LEQUAL); passing pixels
// take the ink, the others are left alone, so any shading (or the program's own picture)
// shows through. ε sets the width.
class PerPixelStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    ShaderProgram mProgram;
    float mEpsilon = 0.2f;
    bool mAntialias = true;
    glm::vec3 mInk{0.0f};
    struct {
        GLint modelview = -1, projection = -1, normalMatrix = -1, orthographic = -1,
              epsilon = -1, inkColor = -1, smoothEdges = -1;
    } mLoc;
};

} // namespace nprgl::styles
