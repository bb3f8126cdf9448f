#pragma once

#include "styles/GlFunctions.h"
#include "styles/MeshBuffers.h"
#include "styles/Scene.h"

#include <string>

namespace nprgl {
class StyleSettings;
}

namespace nprgl::styles {

// What every style of a chain shares in one GL context.
struct StyleContext {
    GlFunctions gl;
    MeshBuffers meshes;
    GLuint vao = 0; // bound when a style's render() starts
    const StyleSettings* settings = nullptr;

    // The value of style.param (configured, else the registry's default).
    double param(const char* style, const char* name) const;
    // A text parameter (file names): configured, else the default text.
    std::string text(const char* style, const char* name) const;
};

// Shading styles draw the held-back surfaces; outline styles draw on top of whatever the
// chain's shading (or, with no shading style, the program itself) left.
enum class StyleRole { Shading, Outline };

// One technique. The compositor creates it when the chain is first used in a context, calls
// init() once, render() at every flush of held-back geometry, shutdown() before the context
// goes. All three run with that context current.
//
// When render() starts, the compositor has saved all of the program's state and set:
// the program's framebuffer and viewport (scene.viewport); the depth buffer holding the
// scene's depth (the held-back draws wrote depth with colour writes off, so earlier forwarded
// 3D drawing depth-tests correctly); ctx.vao bound with attributes 0-3 free; program 0;
// depth test on with GL_LEQUAL and writes on; GL_POLYGON_OFFSET_FILL on at (-1, -1) so a
// re-drawn surface wins against its own depth; blending, culling, stencil, scissor off;
// fill mode; colour mask on; texture unit 0 active. A style may change any state; the
// compositor resets this baseline before the next style and restores the program's after.
class Style {
public:
    virtual ~Style() = default;
    // False with a message when the style cannot run here (the chain then skips it).
    virtual bool init(StyleContext& ctx, std::string& error) = 0;
    virtual void render(const Scene& scene, StyleContext& ctx) = 0;
    virtual void shutdown(StyleContext& ctx) = 0;
};

} // namespace nprgl::styles
