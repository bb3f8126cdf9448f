#pragma once

#include "common/PngImage.h"
#include "styles/Style.h"
#include "styles/strokes/StrokeRenderer.h"

#include <string>

namespace nprgl::styles {

// Geometric strokes (thesis §4.4): per object, silhouette (and optionally crease and border)
// edges are extracted and chained in object space, projected, tested for visibility against
// the scene's depth (occlusion queries or one depth read-back), simplified, cut into strokes
// and drawn as sketchy lines or textured billboards on top of the frame.
class StrokesStyle : public Style {
public:
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    void shutdown(StyleContext& ctx) override;

private:
    void updateTexture(StyleContext& ctx);

    strokes::StrokeRenderer mRenderer;
    std::string mTextureKey; // what the uploaded texture was made from
    PngImage mTextureImage;
};

} // namespace nprgl::styles
