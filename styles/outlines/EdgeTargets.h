#pragma once

#include "styles/GlFunctions.h"

namespace nprgl::styles {

// The off-screen buffers of the image-space outlines, all at the viewport's size and
// recreated only when it changes:
//   geometry pass  - one RGBA32UI target of packed attributes (log view depth, window depth,
//                    colour, object id, eye normal; see EdgesStyle.cpp) and a depth buffer;
//   edge pass      - per pixel: which line classes start here, and its window depth;
//   dilation pass  - the horizontal half of the distance search.
// The last two are only used by lines wider than two pixels.
class EdgeTargets {
public:
    // Makes sure the buffers exist at width x height; false when the driver refuses them.
    bool ensure(const GlFunctions& gl, int width, int height);
    void destroy(const GlFunctions& gl);

    GLuint geometryFbo() const { return mFbo[0]; }
    GLuint edgeFbo() const { return mFbo[1]; }
    GLuint dilateFbo() const { return mFbo[2]; }
    GLuint attributes() const { return mTex[0]; }
    GLuint edges() const { return mTex[1]; }
    GLuint dilated() const { return mTex[2]; }

private:
    GLuint mFbo[3] = {0, 0, 0};
    GLuint mTex[3] = {0, 0, 0};
    GLuint mDepth = 0; // renderbuffer: only tested against, never sampled
    int mWidth = 0;
    int mHeight = 0;
    bool mComplete = false;
};

} // namespace nprgl::styles
