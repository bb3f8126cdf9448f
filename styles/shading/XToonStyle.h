#pragma once

// XToonStyle: X-Toon shading, a 2D tone map indexed by the light and by depth or orientation.

#include "styles/ShaderProgram.h"
#include "styles/Style.h"
#include "styles/shading/ShadingCommon.h"
#include "styles/textures/GlTexture.h"

namespace nprgl::styles {

// X-Toon (Barla, Thollot and Markosian, NPAR 2006): toon shading extended by a second axis.
// The tone comes from a 2D texture at (u, v): u the diffuse term L.n, v a detail attribute,
// either the eye distance between a near and a far plane (level of abstraction: far parts
// lose their bands) or 1 - |n.v|^r (orientation: grazing parts, the silhouettes, take the top
// row's tone, for back-lighting and rim effects). The tone multiplies the object's colour
// (and the program's texture, as detail). The tone map is a user PNG or XToonTexture's.
class XToonStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    struct Variant {
        ShaderProgram program;
        ShadingCommon::ObjectUniforms u;
        GLint depthRange = -1, perspectiveView = -1, toneMap = -1;
    };
    std::string fragmentSource(bool detail, int lights) const;
    bool buildVariant(const GlFunctions& gl, int k, std::string& error);
    // The scene's eye distances: the near and far of the depth axis when not configured.
    glm::vec2 sceneDepthRange(const Scene& scene) const;
    // The depth axis' ends: near and far, each the scene's where not configured.
    glm::vec2 depthRange(const Scene& scene);

    Variant mVariants[ShadingCommon::kVariants]; // ShadingCommon::variantIndex
    uint32_t mVariantsFailed = 0;
    GlTexture mToneMap;
    TextureImage mToneImage;
    bool mOrientation = false;
    bool mDetail = true;
    bool mReflections = false; // generated textures shown (ShadingCommon::withGenerated)
    SceneObject mReflected;    // an object with its generated texture as its own
    bool mWarnedRange = false; // once per chain, not per frame
    float mNear = 0.0f, mFar = 0.0f, mExponent = 2.0f;
};

} // namespace nprgl::styles
