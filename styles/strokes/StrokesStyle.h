#pragma once

#include "common/PngImage.h"
#include "styles/Style.h"
#include "styles/strokes/ChainExtractor.h"
#include "styles/strokes/ChainProjector.h"
#include "styles/strokes/DepthVisibility.h"
#include "styles/strokes/JitterTable.h"
#include "styles/strokes/QueryVisibility.h"
#include "styles/strokes/StrokeBuilder.h"
#include "styles/strokes/StrokeDrawer.h"
#include "styles/strokes/StrokePainter.h"
#include "styles/strokes/StrokeSimplifier.h"

#include <string>
#include <vector>

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

    strokes::ChainExtractor mExtractor;
    strokes::ChainProjector mProjector;
    strokes::DepthVisibility mDepthVisibility;
    strokes::QueryVisibility mQueryVisibility;
    strokes::StrokeSimplifier mSimplifier;
    strokes::StrokeBuilder mBuilder;
    strokes::StrokePainter mPainter;
    strokes::StrokeDrawer mDrawer;
    strokes::JitterTable mJitter;

    strokes::EdgeChains mChains;
    strokes::Polylines mLines, mStrokes;
    std::vector<strokes::StrokeVertex> mVertices;
    std::vector<float> mDepth;
    float mAutoReference = 0.0f; // depth width mode: clip w of the first frame's strokes
    std::string mTextureKey;     // what the uploaded texture was made from
    PngImage mTextureImage;
};

} // namespace nprgl::styles
