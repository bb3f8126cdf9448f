#pragma once

#include "common/PngImage.h"
#include "styles/ShaderProgram.h"
#include "styles/Style.h"
#include "styles/shading/ShadingCommon.h"
#include "styles/strokes/StrokeRenderer.h"
#include "styles/textures/GlTexture.h"
#include "styles/textures/TextureImage.h"

#include <glm/glm.hpp>

#include <string>

namespace nprgl::styles {

// A graphite drawing of the whole frame (HijackGL's pencil renderer): the surfaces become
// paper with hatching whose layers and line weight follow L·n (and, softer, the darkness of
// the program's colour), the outlines several overdrawn, jittered pencil strokes with tapered
// ends (the strokes pipeline); no flat fills. The page is paper.color's; a chain without a
// background style gets paper added (StyleInfo::background). Everything random is fixed per
// line index or mesh vertex, so a still scene is the same drawing in every frame.
class PencilStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    // cut: the variant that takes the program's texture alpha (cut-outs, translucent);
    // lights: how many of the program's lights it sums (ShadingCommon::normalFunction).
    std::string fragmentSource(bool cut, int lights) const;
    // Variant k as ShadingCommon numbers them, "textured" meaning cut.
    bool buildVariant(const GlFunctions& gl, int k, std::string& error);
    void drawSurfaces(const Scene& scene, StyleContext& ctx);

    struct Variant {
        ShaderProgram program;
        ShadingCommon::ObjectUniforms u;
        GLint anchor = -1, grainTex = -1;
    };
    Variant mVariants[ShadingCommon::kVariants];
    uint32_t mVariantsFailed = 0;
    Scene mSolid;         // the objects the strokes outline
    GlTexture mGrainTexture;
    TextureImage mGrainImage;
    strokes::StrokeRenderer mStrokes;
    strokes::StrokeRenderer::Options mStrokeOptions;
    PngImage mStrokeTexture;
    bool mTextureSent = false;

    glm::vec3 mPaper{1.0f}, mGraphite{0.2f};
    float mSpacing = 5.0f, mLineWidth = 1.0f, mAngle = 50.0f, mLight = 0.65f, mDark = -0.2f;
    float mColourTone = 0.5f, mPressure = 0.85f, mGrain = 0.12f;
    // An object with its projected texture as its own (ShadingCommon::withGenerated): a
    // decal's or cut-out's texture darkens its hatching.
    SceneObject mReflected;
    int mLayers = 3;
    bool mFill = true, mOutlines = true;
};

} // namespace nprgl::styles
