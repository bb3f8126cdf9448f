#pragma once

#include "styles/ShaderProgram.h"
#include "styles/Style.h"
#include "styles/outlines/EdgeTargets.h"
#include "styles/outlines/OutlineParams.h"
#include "styles/outlines/TileUnion.h"

#include <glm/glm.hpp>

#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace nprgl::styles {

// Image-space outlines (thesis §4.1.2 and §3.1.4): the whole scene is rendered off screen
// into view depth, eye normals and object ids/colours; an edge operator finds depth
// discontinuities (silhouettes), normal discontinuities (creases) and id or colour changes
// (material edges); a distance search widens each class to its width; the three layers are
// stacked like cels and composited over the framebuffer, depth-tested against the program's
// depth so that anything in front of an outline still hides it. Cut-outs (alpha-tested
// objects) are in the off-screen scene only where the program's alpha test keeps their
// texture, so their lines follow the cut.
//
// Cost on a software rasteriser is per pixel, so every pass is scissored to the window
// rectangle the scene's bounding boxes cover, the attributes are packed into one target,
// and lines of up to two pixels (the default) take a single pass from attributes to the
// composite: their coverage depends only on the pixel's own edge classes. That pass runs on
// the pixels near the scene's feature edges (FeatureLines) rather than the whole rectangle
// where those are fewer.
class EdgesStyle : public Style {
public:
    ~EdgesStyle() override;
    bool init(StyleContext& ctx, std::string& error) override;
    void render(const Scene& scene, StyleContext& ctx) override;
    bool outlinesCutOuts() const override { return true; }
    void shutdown(StyleContext& ctx) override;

private:
    struct Bounds {
        uint64_t contentKey = 0;
        uint32_t geometryVersion = 0;
        uint64_t lastUsed = 0;
        bool cached = false;
        bool empty = true;
        glm::vec3 lo{0.0f}, hi{0.0f};
        // Object-space length per texture coordinate unit (0: not yet measured, -1: none).
        float unitsPerUv = 0.0f;
    };

    void drawFullscreen(const GlFunctions& gl);
    struct Geometry;
    // A cut-out's attributes, with the program's alpha test on its texture.
    void drawCutOut(StyleContext& ctx, const SceneObject& o, const Geometry& u);
    // Whether the direct pass is to run near the objects (each on its feature lines or its
    // box: mNearBy) rather than on the whole rectangle.
    bool planNear(const Scene& scene, StyleContext& ctx, const glm::ivec4& rect);
    // The pixels [lo, hi) of the width x height target the scene (grown by the lines) can
    // touch; false when none.
    bool coveredRect(const Scene& scene, int width, int height, glm::ivec4& rect);
    // Widens [lo, hi] (NDC) by the box's visible part; false if it cannot say.
    static bool boxOnScreen(const glm::mat4& m, const Bounds& b, glm::vec2& lo, glm::vec2& hi);
    // Whether a box [lo, hi] (NDC) lies wholly outside the view, left, right, above or below.
    static bool besideView(const glm::vec2& lo, const glm::vec2& hi);
    const Bounds& bounds(const reconstruct::ObjectMesh& mesh);
    // Object-space length per texture coordinate unit over the mesh's faces (-1: none).
    float unitsPerUv(const reconstruct::ObjectMesh& mesh);
    // An object's box on screen: its larger side in pixels (infinite if it cannot say) and
    // the target's pixels [x0, y0, x1, y1) it covers, grown by the lines' margin.
    struct Footprint {
        float size = INFINITY;
        glm::ivec4 box{0};
        bool fineCut = false; // a cut-out whose cut lines would swamp it (footprint())
        bool onScreen = true; // false: its box is wholly behind the eye or beside the view
    };
    Footprint footprint(const SceneObject& o, int width, int height);

    // [1]: the attributes of cut-outs, kept where the program's alpha test keeps them.
    ShaderProgram mGeometry[2], mDetect, mDilate;
    // Without and with the program's fog on the ink ([1]: kInkFog's INK_FOG).
    ShaderProgram mComposite[2], mDirect[2];
    EdgeTargets mTargets;
    GLuint mTriangle = 0; // one triangle covering the viewport
    bool mWideLines = false;      // lines and points 3 pixels wide can be drawn
    enum class Pass { Auto, Full, Lines } mPass = Pass::Auto; // edges.pass
    std::vector<Footprint> mFootprints; // per object of the flush
    enum class NearBy : uint8_t { None, Lines, Box };
    std::vector<NearBy> mNearBy;        // per object of the flush: planNear's choice
    TileUnion mBoxes{16};               // planNear: the objects run over their boxes
    uint64_t mPasses[2] = {0, 0}; // direct or composite passes: [0] whole rectangle, [1] near
    glm::vec3 mWidths{2.0f};
    InkClass mInks[3]; // silhouette, crease, material
    float mDepthThreshold = 0.05f;
    float mCreaseCosine = 0.6f;
    float mColourThreshold = 0.15f;
    int mRadius = 2;
    int mMargin = 4; // pixels around the scene's bounds that lines may reach
    std::unordered_map<const reconstruct::ObjectMesh*, Bounds> mBounds;
    uint64_t mFlush = 0;
    struct Geometry {
        GLint modelview = -1, projection = -1, normalMatrix = -1, objectId = -1,
              orthographic = -1, depthRange = -1, noMaterial = -1, thinLines = -1,
              cutTexture = -1, cutTextured = -1, alphaFunc = -1, alphaRef = -1;
    };
    Geometry mGeo[2];
    // The edge operator's uniforms, in both programs that run it.
    struct Operator {
        GLint attributes = -1, rect = -1, depthStep = -1, creaseCosine = -1,
              colourThreshold = -1, objectSeams = -1;
    };
    Operator mDet, mDir[2];
    bool mObjectSeams = false;
    float mDetailSize = 64.0f; // pixels: smaller objects get no material lines
    float mThinSize = 32.0f;   // pixels: smaller objects get lines of one pixel
    struct {
        GLint edges = -1, rect = -1, radius = -1;
    } mDil;
    struct {
        GLint dilated = -1, attributes = -1, rect = -1, origin = -1, radius = -1, widths = -1,
              colours = -1, depthBias = -1;
    } mCom[2];
    struct {
        GLint origin = -1, cover = -1, colours = -1, depthBias = -1, modelview = -1,
              projection = -1;
    } mDirU[2];
    // The ink's fog (kInkFog), in both programs that composite.
    struct InkFog {
        GLint mode = -1, range = -1, colour = -1, depth = -1, windowRange = -1;
    };
    InkFog mDirFog[2], mComFog[2];
};

} // namespace nprgl::styles
