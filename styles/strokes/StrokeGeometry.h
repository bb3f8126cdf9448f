#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace nprgl::styles::strokes {

// One corner of a stroke quad, ready for the GL: position in normalised device coordinates
// (w = 1: everything screen-space is done here), the pass's opacity, the arc length along the
// stroke and the stroke's total length in pixels (texture u; negative for a closed loop), the
// side across it (v: 0 or 1) and the line width in pixels at that corner.
struct StrokeVertex {
    float x, y, z, alpha;
    float arc, length, side, width;
};

// Builds screen-space billboards for strokes (thesis §4.4.7, Fig. 4.15-4.16): every segment
// is a quad offset on both sides along the screen normal of its tangent. Inner vertices of a
// stroke share one mitred normal, so neighbouring quads meet without a gap or overlap; the
// ends of a stroke use their own segment's normal (separate across stroke breaks) and are
// extended by half a width so the caps are round rather than cut. Points closer than about
// a line width to the previous one are skipped first: their direction is noise (more so once
// jittered) and their quads would fold over the neighbours and blend twice.
class StrokeGeometry {
public:
    void setViewport(const glm::ivec4& viewport);
    // points: window x, y, depth; widths in pixels; n >= 2. Appends 6 vertices per segment.
    void addStroke(const glm::vec3* points, const float* widths, uint32_t n, bool closed,
                   float alpha, std::vector<StrokeVertex>& out);

private:
    glm::vec2 mOrigin{0.0f}, mScale{1.0f};
    std::vector<glm::vec3> mPoints; // the stroke without points closer than a pixel
    std::vector<float> mWidths;
    std::vector<glm::vec2> mDirection; // per segment, unit
    std::vector<glm::vec2> mOffset;    // per point: unit normal x mitre scale
    std::vector<float> mArc;           // per point
};

} // namespace nprgl::styles::strokes
