#pragma once

// CoverageStyle: the `coverage` debug style: what nprgl styles, and what it leaves.

#include "styles/ShaderProgram.h"
#include "styles/Style.h"
#include "styles/shading/ShadingCommon.h"

namespace nprgl::styles {

// Each styled object flat in a colour of its own (from its id: blues, greens and yellows,
// never red), lit just enough to read its shape. The compositor paints every 3D polygon draw
// it leaves as the program draws it in red (Compositor::tintBegin), so a frame shows at a
// glance which parts of a program nprgl reaches.
class CoverageStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

    // The tint of object `id`: a hue away from red.
    static glm::vec3 colourOf(uint32_t id);

private:
    ShaderProgram mProgram;
    ShadingCommon::ObjectUniforms mU;
    GLint mTint = -1;
    GLint mTextured = -1;
};

} // namespace nprgl::styles
