#pragma once

#include "styles/GlFunctions.h"

namespace nprgl::styles {

// The off-screen buffers of the image-space outlines, all at the viewport's size and
// recreated when it changes:
//   geometry pass  - attributes (view depth, object id, packed colour, coverage), eye normals,
//                    and a depth texture (window depth, for depth-testing the composite);
//   edge pass      - per pixel: which line classes start here, and its window depth;
//   dilation pass  - the horizontal half of the distance search.
class EdgeTargets {
public:
    // Makes sure the buffers exist at width x height; false when the driver refuses them.
    bool ensure(const GlFunctions& gl, int width, int height);
    void destroy(const GlFunctions& gl);

    GLuint geometryFbo() const { return mFbo[0]; }
    GLuint edgeFbo() const { return mFbo[1]; }
    GLuint dilateFbo() const { return mFbo[2]; }
    GLuint attributes() const { return mTex[0]; }
    GLuint normals() const { return mTex[1]; }
    GLuint depth() const { return mTex[2]; }
    GLuint edges() const { return mTex[3]; }
    GLuint dilated() const { return mTex[4]; }

private:
    GLuint mFbo[3] = {0, 0, 0};
    GLuint mTex[5] = {0, 0, 0, 0, 0};
    int mWidth = 0;
    int mHeight = 0;
    bool mComplete = false;
};

} // namespace nprgl::styles
