#include "styles/strokes/StrokeSimplifier.h"

#include <algorithm>

namespace nprgl::styles::strokes {

namespace {

bool collinear(const Polylines& lines, uint32_t previous, uint32_t current, uint32_t next)
{
    if (lines.edge[previous] == lines.edge[current]) return true;
    const glm::vec3 a = lines.points[current].object - lines.points[previous].object;
    const glm::vec3 b = lines.points[next].object - lines.points[current].object;
    const float la = glm::dot(a, a), lb = glm::dot(b, b);
    const glm::vec3 c = glm::cross(a, b);
    return glm::dot(a, b) > 0.0f && glm::dot(c, c) <= 1e-12f * la * lb;
}

// Drops the inner points `drop(last, i)` picks, polyline by polyline, compacting in place
// (`last` is the index, after compaction, of the previous kept point). Returns how many.
template <typename Drop>
uint32_t compact(Polylines& lines, Drop&& drop)
{
    uint32_t write = 0, removed = 0, newStart = 0;
    for (uint32_t p = 0; p < lines.count(); ++p) {
        const uint32_t begin = lines.start[p], end = lines.start[p + 1];
        lines.start[p] = newStart;
        uint32_t last = 0;
        for (uint32_t i = begin; i < end; ++i) {
            if (i > begin && i + 1 < end && drop(last, i)) {
                ++removed;
                continue;
            }
            lines.points[write] = lines.points[i];
            lines.edge[write] = lines.edge[i];
            lines.state[write] = lines.state[i];
            last = write++;
        }
        newStart = write;
    }
    lines.start[lines.count()] = newStart;
    lines.points.resize(write);
    lines.edge.resize(write);
    lines.state.resize(write);
    return removed;
}

} // namespace

uint32_t StrokeSimplifier::simplify(Polylines& lines) const
{
    // Point i goes when it joins two visible, exactly collinear segments: the kept previous
    // point's segment then reaches i + 1.
    return compact(lines, [&lines](uint32_t last, uint32_t i) {
        return lines.state[last] == kVisible && lines.state[i] == kVisible &&
               collinear(lines, last, i, i + 1);
    });
}

uint32_t StrokeSimplifier::removeFolds(Polylines& lines, float maxLength) const
{
    if (maxLength <= 0.0f) return 0;
    constexpr float kTurnBack = -0.5f; // cos 120 degrees
    return compact(lines, [&](uint32_t last, uint32_t i) {
        if (lines.state[last] != kVisible || lines.state[i] != kVisible) return false;
        const glm::vec2 a =
            glm::vec2(lines.points[i].window) - glm::vec2(lines.points[last].window);
        const glm::vec2 b =
            glm::vec2(lines.points[i + 1].window) - glm::vec2(lines.points[i].window);
        const float la = glm::length(a), lb = glm::length(b);
        return la > 0.0f && lb > 0.0f && std::min(la, lb) < maxLength &&
               glm::dot(a, b) < kTurnBack * la * lb;
    });
}

} // namespace nprgl::styles::strokes
