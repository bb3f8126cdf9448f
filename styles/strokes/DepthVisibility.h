#pragma once

#include "reconstruct/ObjectMesh.h"
#include "styles/strokes/StrokeTypes.h"

#include <cstdint>
#include <vector>

namespace nprgl::styles::strokes {

// A window-depth image: depth[(y - y0) * width + (x - x0)], bottom row first (as
// glReadPixels gives it), values in [0, 1].
struct DepthImage {
    const float* depth = nullptr;
    int x0 = 0, y0 = 0, width = 0, height = 0;
};

// The fast visibility test: one depth read-back per frame instead of two occlusion queries
// per segment. Each unknown segment is sampled about every `step` pixels; a sample is visible
// when its tolerance-biased depth is not behind the farthest depth of the (2r+1)^2 pixels
// around it (a silhouette always has the far side next to it; an occluder covers the whole
// neighbourhood). Segments are split where the samples change their mind, at the middle
// between the two samples; a lone sample that disagrees with both neighbours is ignored.
// Pure CPU: testable and benchmarkable without GL.
class DepthVisibility {
public:
    struct Options {
        int radius = 1;
        float step = 1.0f;
    };

    // Replaces `lines` by the classified (and split) polylines; every segment ends up visible
    // or hidden. mesh gives the edges' end vertices for split points.
    void classify(const reconstruct::ObjectMesh& mesh, const DepthImage& image,
                  const Options& options, Polylines& lines);

private:
    bool sampleVisible(const DepthImage& image, int radius, float x, float y,
                       float depth) const;

    Polylines mOut;
    std::vector<uint8_t> mSamples;
};

} // namespace nprgl::styles::strokes
