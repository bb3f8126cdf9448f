#pragma once

#include "styles/ShaderProgram.h"
#include "styles/Style.h"
#include "styles/shading/ShadingCommon.h"
#include "styles/textures/GlTexture.h"
#include "styles/textures/TextureImage.h"

#include <glm/glm.hpp>

#include <string>

namespace nprgl::styles {

// Half-toning (thesis §3.3, after Freudenberg): three screens A, B, C folded into one texture
// H; per pixel the illumination I = a + ((L·n + 1) / 2)^α · d (eq. 3.13), times a detail
// map T (the program's texture, else 1), decides the ink through C_f = 1 − S(1 − I·T − H)
// (eq. 3.14, clamped), which is near-binary: ink or paper.
class HalftoneStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    // One program per kind of object: [0] untextured, [1] textured (detail map, object space).
    struct Variant {
        ShaderProgram program;
        ShadingCommon::ObjectUniforms u;
        GLint anchor = -1, screen = -1;
        bool configured = false; // its sampler units are set
    };
    std::string fragmentSource(bool textured, int lights) const;
    bool buildVariant(const GlFunctions& gl, int k, std::string& error);
    bool screenMipmaps() const;

    Variant mVariants[ShadingCommon::kVariants]; // ShadingCommon::variantIndex
    uint32_t mVariantsFailed = 0;
    TextureImage mScreenImage; // combined H, uploaded on first render
    GlTexture mScreen;
    float mAmbient = 0.0f, mDiffuse = 1.0f, mGamma = 1.0f, mSmoothness = 6.0f, mScale = 1.0f;
    float mDetailStrength = 0.6f;
    bool mDetail = true, mObjectSpace = false, mInkFromObject = false;
    bool mReflections = false; // generated textures shown (ShadingCommon::withGenerated)
    SceneObject mReflected;    // an object with its generated texture as its own
    glm::vec3 mInk{0.0f}, mPaper{1.0f};
};

} // namespace nprgl::styles
