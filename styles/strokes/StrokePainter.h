#pragma once

#include "reconstruct/ObjectMesh.h"
#include "styles/strokes/JitterTable.h"
#include "styles/strokes/StrokeGeometry.h"
#include "styles/strokes/StrokeTypes.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace nprgl::styles::strokes {

// Turns one object's strokes into quads for the GL (thesis §4.4.7), on the CPU: line width
// per point by the chosen mode, and N overdraw passes, each with every point moved by its
// mesh vertices' precomputed jitter in the local frame (edge tangent, view vector, their
// cross product), scaled so that `jitter` is in pixels whatever the distance.
class StrokePainter {
public:
    enum class WidthMode { Fixed = 0, Depth = 1, Stroke = 2, Light = 3 };
    enum class JitterMode { Random = 0, Normal = 1 };

    struct Options {
        WidthMode widthMode = WidthMode::Fixed;
        float width = 2.5f;          // pixels (fixed; depth mode at depthReference)
        float minWidth = 1.0f;       // pixels
        float maxWidth = 4.0f;       // pixels
        float widthScale = 1.2f;     // stroke mode: growth per point
        float depthReference = 1.0f; // depth mode: clip w at which the width is `width`
        uint32_t passes = 1;
        float jitter = 0.0f;         // pixels
        JitterMode jitterMode = JitterMode::Random;
        uint32_t seed = 1;
        float opacity = 1.0f;
        bool biasedDepth = false;    // z-buffer mode: use the tolerance-biased depth
    };
    struct View {
        glm::mat4 modelview{1.0f};
        glm::mat4 projection{1.0f};
        glm::ivec4 viewport{0, 0, 1, 1};
        glm::vec3 lightDir{0.0f, 0.0f, 1.0f}; // eye space, unit
    };

    void paint(const reconstruct::ObjectMesh& mesh, const Polylines& strokes, const View& view,
               const Options& options, JitterTable& jitter, std::vector<StrokeVertex>& out);

private:
    StrokeGeometry mGeometry;
    std::vector<glm::vec3> mPoints;
    std::vector<float> mWidths;
    std::vector<float> mLightWidths; // per stroke point (light mode)
};

} // namespace nprgl::styles::strokes
