#pragma once

#include "styles/ShaderProgram.h"
#include "styles/Style.h"
#include "styles/background/ScreenCopy.h"
#include "styles/textures/GlTexture.h"
#include "styles/textures/TextureImage.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace nprgl::styles {

// The page the picture is drawn on (thesis 2.4.2 and appendix B: a background image before
// the frame, a paper structure blended over it after). Where the program left its cleared
// background untouched - far depth and still the clear colour - the page shows paper (a flat
// colour or a tiled scan); then a fine paper grain darkens the whole viewport, the scene
// included, fixed to the screen like a real sheet. The page goes under the scene (so a surface
// the program draws in its clear colour without depth stays the program's: see
// Style::keepBackground); the grain after shading, before the ink.
class PaperStyle : public Style {
public:
    // Whether the settings give paper.color another colour than the default (then into
    // `colour`): a chosen page, whatever the program's background.
    static bool colourConfigured(const StyleContext& ctx, glm::vec3& colour);

    bool init(StyleContext& ctx, std::string& error) override;
    void keepBackground(const Scene& scene, StyleContext& ctx) override;
    void layBackground(const Scene& scene, StyleContext& ctx) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    struct Uniforms {
        GLint colour = -1, grainTex = -1, paperTex = -1, origin = -1, usePaperTex = -1,
              paperColour = -1, clearColour = -1, tolerance = -1, grain = -1, pass = -1,
              grainSize = -1, paperSize = -1, compare = -1;
    };
    // Whether this frame's grain already lies over the viewport (a second flush in one
    // frame must not darken the page twice); mark: and it does from now on.
    bool grainedThisFrame(const Scene& scene, bool mark);
    // The shared set-up of both passes: program, uniforms, textures, the full-view triangle.
    void beginPass(const Scene& scene, StyleContext& ctx);
    void endPass(const Scene& scene, StyleContext& ctx);
    // True when this frame's page is already under the scene's viewport of its framebuffer
    // and the program cleared no colour since: the background left is paper already.
    // mark: and it is from now on.
    bool filledAlready(const Scene& scene, bool mark);
    // Copies what the program left in the viewport (false, said once, when it cannot).
    bool copyBackground(const Scene& scene, StyleContext& ctx);

    ShaderProgram mProgram;
    Uniforms mU;
    GLuint mTriangle = 0;
    ScreenCopy mCopy;
    GlTexture mGrainTexture, mPaperTexture;
    TextureImage mGrainImage, mPaperImage; // uploaded at the first render()
    bool mWarnedCopy = false;
    // keepBackground's copy of this flush (the scene's frame and viewport), not yet laid.
    bool mKept = false;
    uint64_t mKeptFrame = UINT64_MAX;
    glm::ivec4 mKeptViewport{0};
    uint64_t mGrainFrame = UINT64_MAX;
    std::vector<glm::ivec4> mGrainedViewports;
    struct Filled {
        uint32_t framebuffer;
        glm::ivec4 viewport;
        uint64_t colourClears;
        bool operator==(const Filled&) const = default;
    };
    uint64_t mFillFrame = UINT64_MAX;
    std::vector<Filled> mFilled;
    // Parameters, fixed for the chain's life.
    glm::vec3 mPaperColour{0.957f, 0.937f, 0.882f};
    glm::vec3 mDarkColour{0.082f, 0.090f, 0.102f}; // the page when PageTone says dark
    bool mColourChosen = false;                    // paper.color set: the page, dark or light
    bool mFill = true;
    float mGrain = 0.12f;
    bool mGrainScene = false; // grain over the scene too, not only the paper
    float mGrainScale = 1.0f;
};

} // namespace nprgl::styles
