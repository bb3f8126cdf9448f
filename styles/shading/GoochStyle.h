#pragma once

#include "styles/ShaderProgram.h"
#include "styles/Style.h"
#include "styles/shading/ShadingCommon.h"
#include "styles/textures/GlTexture.h"

namespace nprgl::styles {

// Technical illustration shading (Gooch, Gooch, Shirley and Cohen, SIGGRAPH 1998): the tone
// goes from a cool colour facing away from the light to a warm colour facing it, each mixed
// with the object's own colour, so shape reads from hue as well as brightness and no part
// falls to black; an optional white highlight. The pure tones may come from a user's PNG.
class GoochStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    // [0] untextured objects, [1] the program's texture modulating the tone.
    struct Variant {
        ShaderProgram program;
        ShadingCommon::ObjectUniforms u;
        GLint ramp = -1;
    };
    std::string fragmentSource(bool detail, int lights) const;
    bool buildVariant(const GlFunctions& gl, int k, std::string& error);
    TextureImage generatedRamp() const;

    Variant mVariants[ShadingCommon::kVariants]; // ShadingCommon::variantIndex
    uint32_t mVariantsFailed = 0;
    float mBlue = 0.4f, mYellow = 0.4f, mAlpha = 0.2f, mBeta = 0.6f;
    float mHighlight = 0.0f; // exponent of the white highlight (0: none)
    bool mDetail = true;
    bool mReflections = false; // generated textures shown (ShadingCommon::withGenerated)
    SceneObject mReflected;    // an object with its generated texture as its own
    TextureImage mRampImage; // the pure tones, cool to warm
    GlTexture mRamp;
};

} // namespace nprgl::styles
