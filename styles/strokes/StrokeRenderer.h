#pragma once

#include "common/PngImage.h"
#include "styles/GlFunctions.h"
#include "styles/Scene.h"
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

namespace nprgl::styles::strokes {

// The geometric-stroke pipeline of thesis §4.4 from a scene to strokes on the screen:
// extraction and chaining in object space, projection, visibility, simplification, stroke
// building, painting (width, overdraw jitter) and drawing. The styles that draw strokes
// (strokes, pencil) own one each and fill its options from their parameters.
class StrokeRenderer {
public:
    enum class Visibility {
        Query,   // occlusion queries per segment with refinement (§4.4.4)
        Depth,   // one depth read-back, sampled along each segment
        ZBuffer, // no visibility stage: the strokes are depth-tested against the scene
    };
    struct Options {
        Visibility visibility = Visibility::Depth;
        ChainExtractor::Options extract;
        float depthTolerance = 0.01f; // fraction of the line's eye distance
        DepthVisibility::Options depth;
        QueryVisibility::Options query;
        float foldLength = 6.0f; // pixels; 0 keeps zig-zags
        StrokeBuilder::Options build;
        // depthReference <= 0 in depth width mode: the mean clip w of the first strokes.
        StrokePainter::Options paint;
        StrokeDrawer::Options draw;
    };

    bool init(const GlFunctions& gl, std::string& error);
    void destroy(const GlFunctions& gl);
    // The texture of the textured renderer (RGBA8, u along the stroke).
    void setTexture(const GlFunctions& gl, const PngImage& image);
    // Draws the strokes of every object of the scene with the current GL state of Style.h's
    // outline baseline; options.paint.biasedDepth and options.draw.depthTest follow from
    // the visibility mode.
    void render(const Scene& scene, const GlFunctions& gl, Options options);

private:
    ChainExtractor mExtractor;
    ChainProjector mProjector;
    DepthVisibility mDepthVisibility;
    QueryVisibility mQueryVisibility;
    StrokeSimplifier mSimplifier;
    StrokeBuilder mBuilder;
    StrokePainter mPainter;
    StrokeDrawer mDrawer;
    JitterTable mJitter;

    EdgeChains mChains;
    Polylines mLines, mStrokes;
    std::vector<StrokeVertex> mVertices;
    std::vector<float> mDepth;
    float mAutoReference = 0.0f; // depth width mode: clip w of the first frame's strokes
};

} // namespace nprgl::styles::strokes
