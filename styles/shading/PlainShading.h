#pragma once

#include "styles/Scene.h"
#include "styles/shading/ShadingCommon.h"

#include <string>

namespace nprgl::styles {

// Objects drawn as the fixed pipeline drew them unlit: the program's colour (lit colours as
// the tracker took them), its texture modulating, its fog; no style. For a scene the program
// reads back (colour-coded picking), whose pixels are data, not picture.
class PlainShading {
public:
    bool init(const GlFunctions& gl, std::string& error);
    // Draws `scene`'s objects with the state the caller set (depth, blending, alpha test).
    void render(const Scene& scene, StyleContext& ctx);
    void shutdown(const GlFunctions& gl);

private:
    struct Variant {
        ShaderProgram program;
        ShadingCommon::ObjectUniforms u;
    };
    Variant mVariants[2]; // untextured, textured
};

} // namespace nprgl::styles
