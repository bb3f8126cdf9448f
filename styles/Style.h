#pragma once

#include "styles/GlFunctions.h"
#include "styles/MeshBuffers.h"
#include "styles/PageTone.h"
#include "styles/Scene.h"

#include <cstdint>
#include <functional>
#include <string>

namespace nprgl {
class StyleSettings;
}

namespace nprgl::styles {

class AbstractTextures;

// What every style of a chain shares in one GL context.
struct StyleContext {
    GlFunctions gl;
    MeshBuffers meshes;
    GLuint vao = 0; // bound when a style's render() starts
    GLuint blankTexture = 0; // 1x1 white, made on first use (ShadingCommon::drawTextured)
    const StyleSettings* settings = nullptr;
    bool alphaWrites = true; // the scene's (Scene::alphaWrites), set by the chain per flush
    PageTone page;           // dark or light this frame (the chain observes each flush)
    // The program's textures as drawings (AbstractTextures, the chain's): a shading style
    // sets textureDetail below 1 while it draws to have them bound in place of the program's.
    AbstractTextures* abstractions = nullptr;
    float textureDetail = 1.0f;
    uint64_t frame = 0; // the scene's (Scene::frame), set by the chain per flush
    // A program texture's content hash (0: not known), from the compositor's state model.
    std::function<uint64_t(GLuint)> textureContent;

    // The value of style.param (configured, else the registry's default).
    double param(const char* style, const char* name) const;
    // A text parameter (file names): configured, else the default text.
    std::string text(const char* style, const char* name) const;
    // A colour parameter: configured, else `fallback` ("rrggbb"), with a message when the
    // configured text is empty or not a colour.
    glm::vec3 colour(const char* style, const char* name, const char* fallback) const;

    // A style's own scissor rectangle (x, y, width, height, window pixels), confined to the
    // scene's scissor box; and back to the baseline (the scene's box, or no test).
    void scissorTo(const Scene& scene, glm::ivec4 rect) const;
    void endScissor(const Scene& scene) const;
    // Every colour channel on, alpha as the program writes it in this scene.
    void colourMaskOn() const { gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, alphaWrites); }
};

// Shading styles draw the held-back surfaces; background styles then restyle the page around
// (and under) them; outline styles draw on top of whatever the chain's shading (or, with no
// shading style, the program itself) and background left.
enum class StyleRole { Shading, Background, Outline };

// One technique. The compositor creates it when the chain is first used in a context, calls
// init() once, render() at every flush of held-back geometry, shutdown() before the context
// goes. All three run with that context current.
//
// When render() starts, the compositor has saved all of the program's state and set:
// the program's framebuffer and viewport (scene.viewport); ctx.vao bound with attributes 0-3
// free; program 0; blending, culling, stencil off; the scissor test as the program drew the
// scene (scene.scissored, scene.scissor; off for most); fill mode; colour mask on;
// texture unit 0 active. The depth buffer holds what the program drew before, but not the
// held-back scene: the held draws reached the driver with neither colour nor depth (when the
// chain has a shading style) or as the program made them (when it has none).
// - A shading style runs first, with depth test GL_LESS and depth writes on: it draws the
//   scene's surfaces and their depth, so everything after it sees the whole scene.
// - Background and outline styles run after it with depth test GL_LEQUAL, depth writes on
//   and GL_POLYGON_OFFSET_FILL at (-1, -1), so a re-drawn surface wins against its own depth.
// A style may change any state; the compositor resets this baseline before the next style
// and restores the program's after the chain.
class Style {
public:
    virtual ~Style() = default;
    // False with a message when the style cannot run here (the chain then skips it).
    virtual bool init(StyleContext& ctx, std::string& error) = 0;
    virtual void render(const Scene& scene, StyleContext& ctx) = 0;
    // A background style's, first in a flush, before anything of it is drawn (with the
    // baseline of the styles after shading): what goes behind all of the program's drawing
    // (the page). Or, when nothing in the flush is drawn without the depth test, only keep
    // what the program left (keepBackground) and lay the page after the opaque scene, whose
    // depth then spares its pixels the page's work (layBackground, from render or the chain).
    virtual void keepBackground(const Scene&, StyleContext&) {}
    virtual void layBackground(const Scene&, StyleContext&) {}
    // An outline style that draws cut-outs' lines along their cuts (the program's alpha test
    // on their texture) is given them with the opaque scene; others are not (a cut-out's
    // polygons are not its shape).
    virtual bool outlinesCutOuts() const { return false; }
    virtual void shutdown(StyleContext& ctx) = 0;
};

} // namespace nprgl::styles
