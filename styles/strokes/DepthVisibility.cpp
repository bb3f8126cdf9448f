#include "styles/strokes/DepthVisibility.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace nprgl::styles::strokes {

bool DepthVisibility::sampleVisible(const DepthImage& image, int radius, float x, float y,
                                    float depth) const
{
    const int px = int(std::floor(x)) - image.x0, py = int(std::floor(y)) - image.y0;
    // Outside the read-back area nothing can hide the line (the GL clips it anyway).
    if (px < 0 || py < 0 || px >= image.width || py >= image.height) return true;
    const int xa = std::max(px - radius, 0), xb = std::min(px + radius, image.width - 1);
    const int ya = std::max(py - radius, 0), yb = std::min(py + radius, image.height - 1);
    float farthest = 0.0f;
    for (int j = ya; j <= yb; ++j) {
        const float* row = image.depth + size_t(j) * size_t(image.width);
        for (int i = xa; i <= xb; ++i) farthest = std::max(farthest, row[i]);
    }
    return depth <= farthest;
}

void DepthVisibility::classify(const reconstruct::ObjectMesh& mesh, const DepthImage& image,
                               const Options& options, Polylines& lines)
{
    mOut.clear();
    mOut.points.reserve(lines.points.size());
    const float step = std::max(options.step, 0.25f);
    for (uint32_t p = 0; p < lines.count(); ++p) {
        const uint32_t begin = lines.start[p], end = lines.start[p + 1];
        for (uint32_t i = begin; i + 1 < end; ++i) {
            const ChainPoint& a = lines.points[i];
            const ChainPoint& b = lines.points[i + 1];
            const uint32_t edge = lines.edge[i];
            if (lines.state[i] != kUnknown) {
                mOut.addPoint(a, edge, lines.state[i]);
                continue;
            }
            const glm::vec2 delta = glm::vec2(b.window) - glm::vec2(a.window);
            const float length = glm::length(delta);
            const int n = std::clamp(int(std::ceil(length / step)), 1, 1 << 16);
            mSamples.resize(size_t(n));
            for (int k = 0; k < n; ++k) {
                const float s = (float(k) + 0.5f) / float(n);
                const float depth = a.biasedDepth + (b.biasedDepth - a.biasedDepth) * s;
                mSamples[size_t(k)] = sampleVisible(image, options.radius, a.window.x + delta.x * s,
                                                    a.window.y + delta.y * s, depth)
                                          ? kVisible
                                          : kHidden;
            }
            for (int k = 1; k + 1 < n; ++k) {
                if (mSamples[k - 1] == mSamples[k + 1] && mSamples[k] != mSamples[k - 1])
                    mSamples[k] = mSamples[k - 1];
            }
            mOut.addPoint(a, edge, mSamples[0]);
            const reconstruct::EdgeInfo& info = mesh.edges[edge];
            for (int k = 1; k < n; ++k) {
                if (mSamples[k] == mSamples[k - 1]) continue;
                mOut.addPoint(splitPoint(a, b, float(k) / float(n), info.v0, info.v1), edge,
                              mSamples[k]);
            }
        }
        mOut.addPoint(lines.points[end - 1], 0, kUnknown);
        mOut.endPolyline(lines.closed[p] != 0);
    }
    std::swap(mOut, lines);
}

} // namespace nprgl::styles::strokes
