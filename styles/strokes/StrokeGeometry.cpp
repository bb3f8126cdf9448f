#include "styles/strokes/StrokeGeometry.h"

#include <algorithm>

namespace nprgl::styles::strokes {

namespace {

constexpr float kMaxMitre = 2.0f;
constexpr float kFeather = 0.75f; // pixels added on each side for a soft edge
// Consecutive stroke points at least this far apart (pixels, and times the width): shorter
// quads would fold over their neighbours at a turn and blend twice.
constexpr float kMinSpacing = 1.0f;
constexpr float kSpacingPerWidth = 0.75f;

glm::vec2 perp(glm::vec2 d) { return {-d.y, d.x}; }

} // namespace

void StrokeGeometry::setViewport(const glm::ivec4& viewport)
{
    mOrigin = glm::vec2(viewport.x, viewport.y);
    mScale = glm::vec2(2.0f / float(std::max(viewport.z, 1)),
                       2.0f / float(std::max(viewport.w, 1)));
}

void StrokeGeometry::addStroke(const glm::vec3* input, const float* inputWidths, uint32_t count,
                               bool closed, float alpha, std::vector<StrokeVertex>& out)
{
    if (count < 2) return;
    mPoints.clear();
    mWidths.clear();
    for (uint32_t i = 0; i < count; ++i) {
        const bool last = i + 1 == count;
        if (!mPoints.empty() &&
            glm::distance(glm::vec2(input[i]), glm::vec2(mPoints.back())) <
                std::max(kMinSpacing, kSpacingPerWidth * inputWidths[i])) {
            // Keep the end point exactly (a loop must close); it replaces a near one.
            if (!last || mPoints.size() < 2) continue;
            mPoints.pop_back();
            mWidths.pop_back();
        }
        mPoints.push_back(input[i]);
        mWidths.push_back(inputWidths[i]);
    }
    const uint32_t n = uint32_t(mPoints.size());
    if (n < 2) return;
    const glm::vec3* points = mPoints.data();
    const float* widths = mWidths.data();
    const uint32_t segments = n - 1;
    mDirection.resize(segments);
    bool any = false;
    for (uint32_t i = 0; i < segments; ++i) {
        const glm::vec2 d = glm::vec2(points[i + 1]) - glm::vec2(points[i]);
        const float len = glm::length(d);
        mDirection[i] = len > 1e-4f ? d / len : glm::vec2(0.0f);
        any = any || len > 1e-4f;
    }
    if (!any) return;
    // Degenerate segments borrow a neighbour's direction.
    for (uint32_t i = 1; i < segments; ++i)
        if (mDirection[i] == glm::vec2(0.0f)) mDirection[i] = mDirection[i - 1];
    for (uint32_t i = segments - 1; i-- > 0;)
        if (mDirection[i] == glm::vec2(0.0f)) mDirection[i] = mDirection[i + 1];

    mOffset.resize(n);
    mArc.resize(n);
    for (uint32_t i = 0; i < n; ++i) {
        const bool inner = i > 0 && i + 1 < n;
        glm::vec2 in, outDir;
        if (inner) {
            in = mDirection[i - 1];
            outDir = mDirection[i];
        } else if (closed) {
            in = mDirection[segments - 1];
            outDir = mDirection[0];
        } else {
            in = outDir = mDirection[i == 0 ? 0 : segments - 1];
        }
        // One shared (mitred) normal, so both quads at this vertex use the same corners.
        glm::vec2 tangent = in + outDir;
        const float tl = glm::length(tangent);
        tangent = tl > 1e-4f ? tangent / tl : outDir;
        const glm::vec2 normal = perp(tangent);
        const float c = std::max(glm::dot(normal, perp(outDir)), 1.0f / kMaxMitre);
        mOffset[i] = normal / c;
        mArc[i] = i == 0 ? 0.0f
                         : mArc[i - 1] + glm::distance(glm::vec2(points[i]),
                                                       glm::vec2(points[i - 1]));
    }
    // Open strokes reach half a width past their ends (round-ish caps, no cut-off look).
    const float startCap = closed ? 0.0f : 0.5f * widths[0];
    const float endCap = closed ? 0.0f : 0.5f * widths[n - 1];
    const float total = mArc[n - 1] + startCap + endCap;

    auto corner = [&](uint32_t i, float side, float extend) {
        const float half = 0.5f * widths[i] + kFeather;
        glm::vec2 p = glm::vec2(points[i]) + mOffset[i] * (side * half);
        glm::vec2 along(0.0f);
        if (extend != 0.0f) along = mDirection[i == 0 ? 0 : segments - 1] * extend;
        p += along;
        const glm::vec2 ndc = (p - mOrigin) * mScale - 1.0f;
        StrokeVertex v;
        v.x = ndc.x;
        v.y = ndc.y;
        v.z = 2.0f * points[i].z - 1.0f;
        v.alpha = alpha;
        v.arc = mArc[i] + startCap + extend;
        v.length = closed ? -total : total; // negative: a loop, no caps
        v.side = side < 0.0f ? 0.0f : 1.0f;
        v.width = widths[i];
        return v;
    };
    for (uint32_t i = 0; i < segments; ++i) {
        const float e0 = i == 0 ? -startCap : 0.0f;
        const float e1 = i + 1 == segments ? endCap : 0.0f;
        const StrokeVertex a = corner(i, -1.0f, e0), b = corner(i, 1.0f, e0);
        const StrokeVertex c = corner(i + 1, -1.0f, e1), d = corner(i + 1, 1.0f, e1);
        out.insert(out.end(), {a, c, d, a, d, b});
    }
}

} // namespace nprgl::styles::strokes
