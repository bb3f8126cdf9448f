#pragma once

#include "styles/ShaderProgram.h"
#include "styles/Style.h"
#include "styles/shading/ShadingCommon.h"
#include "styles/textures/GlTexture.h"
#include "styles/textures/TextureImage.h"

#include <glm/glm.hpp>

#include <string>

namespace nprgl::styles {

// Textured shading (thesis §3.2): cartoon shading whose lit region carries a light texture
// and whose shadowed region carries a shadow texture, blended by an alpha ramp over
// [ta_l, ta_u] that is independent of t_d. The ramp is either symmetric (one cross-fade) or
// non-symmetric (fig. 3.13: both textures overlap inside the band and each falls off
// steeply, which suits stroke textures). The highlight variant centres the band on t_h and
// keeps the detail texture out of the highlight.
class TexturedStyle : public Style {
public:
    // What a layer shows (the values of the light_texture and shadow_texture choices).
    enum Source { None, Paper, Hatching, CrossHatching, Stipple, Program };

    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    struct Layer {
        Source source = None;
        TextureImage image; // procedural or PNG, uploaded on first render
        GlTexture texture;
    };
    // One program per kind of object: [0] untextured, [1] textured (the program's texture
    // as a layer, object space).
    struct Variant {
        ShaderProgram program;
        ShadingCommon::ObjectUniforms u;
        GLint anchor = -1, lightTex = -1, shadowTex = -1;
        bool configured = false; // its sampler units are set
    };
    void prepareLayer(StyleContext& ctx, Layer& layer, const char* choice, const char* png);
    std::string fragmentSource(bool textured, int lights) const;
    bool buildVariant(const GlFunctions& gl, int k, std::string& error);
    std::string layerFunction(const char* name, const Layer& layer, int mode, const char* sampler,
                              bool objectSpace) const;
    bool layerMipmaps() const;
    Variant mVariants[ShadingCommon::kVariants]; // ShadingCommon::variantIndex
    uint32_t mVariantsFailed = 0;
    Layer mLight, mShadow;
    bool mUploaded = false;
    int mTones = 2;
    float mDiffuseThreshold = 0.0f, mHighlightThreshold = 0.9f;
    float mShadowScale = 0.7f, mHighlightMix = 0.5f;
    bool mReflections = false; // generated textures shown (ShadingCommon::withGenerated)
    SceneObject mReflected;    // an object with its generated texture as its own
    float mBandLow = -0.1f, mBandHigh = 0.1f, mFalloff = 0.35f, mScale = 1.0f;
    bool mAsymmetric = false, mTint = true, mHighlightVariant = false, mObjectSpace = false;
};

} // namespace nprgl::styles
