#pragma once

#include "styles/ShaderProgram.h"
#include "styles/Style.h"
#include "styles/shading/ShadingCommon.h"

#include <glm/glm.hpp>

#include <string>

namespace nprgl::styles {

// Cartoon shading (thesis §3.1 and the future work of §3.1.4): per pixel, L·n below t_d takes
// the shadow colour, above t_h the highlight colour, else the diffuse colour; all three
// derived from the program's own colour or material unless configured. Optional: band
// boundaries antialiased in screen space, ink lines between the bands (fig. 3.8), and the
// program's texture as a detail texture (modulated or as a decal "sticker").
class ToonStyle : public Style {
public:
    // toon.texture_detail's default: chosen by looking at the textured games of the corpus.
    static constexpr double kDefaultTextureDetail = 0.3;

    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    // One program per detail mode actually drawn: [0] untextured objects, [1] the detail.
    struct Variant {
        ShaderProgram program;
        ShadingCommon::ObjectUniforms u;
    };
    std::string fragmentSource(int detail, int lights) const;
    bool buildVariant(const GlFunctions& gl, int k, std::string& error);

    Variant mVariants[ShadingCommon::kVariants]; // ShadingCommon::variantIndex
    uint32_t mVariantsFailed = 0;
    // Parameters: fixed for the chain's life, so read once at init.
    int mTones = 3;
    float mDiffuseThreshold = 0.0f, mHighlightThreshold = 0.9f;
    float mShadowScale = 0.55f, mShadowFloor = 0.3f, mHighlightMix = 0.5f;
    bool mProgramBands = true; // bands by GL's own light where the program lit (toon.bands)
    bool mHalfBand = true;     // and a half-shadow band between shadow and full colour there
    bool mSmooth = true, mBandLines = false;
    float mLineWidth = 1.5f;
    float mTextureDetail = 1.0f;
    int mDetail = 1; // 0 off, 1 modulate, 2 decal
    bool mReflections = false; // generated textures shown as detail
    SceneObject mReflected;    // an object with its generated texture as its own
    int mFixed = 0; // bit i: colour i (shadow, diffuse, highlight) is configured
    glm::vec3 mColors[3]{};
};

} // namespace nprgl::styles
