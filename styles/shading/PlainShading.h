#pragma once

#include "styles/Scene.h"
#include "styles/shading/ShadingCommon.h"

#include <string>

namespace nprgl::styles {

// Objects drawn as the fixed pipeline drew them: the program's colour (lit colours as the
// tracker took them), its textures and lightmaps modulating (generated coordinates as GL
// generates them), its fog; no style. For a scene the program reads back (colour-coded
// picking), whose pixels are data, not picture; and the `replica` style.
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
    SceneObject mGenerated; // an object with its generated texture as its own
};

} // namespace nprgl::styles
