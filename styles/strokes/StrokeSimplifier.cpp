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

} // namespace

uint32_t StrokeSimplifier::simplify(Polylines& lines) const
{
    uint32_t write = 0;
    uint32_t removed = 0;
    uint32_t newStart = 0;
    for (uint32_t p = 0; p < lines.count(); ++p) {
        const uint32_t begin = lines.start[p], end = lines.start[p + 1];
        lines.start[p] = newStart;
        uint32_t last = 0; // index (after compaction) of the previous kept point
        for (uint32_t i = begin; i < end; ++i) {
            const bool inner = i > begin && i + 1 < end;
            if (inner && lines.state[last] == kVisible && lines.state[i] == kVisible &&
                collinear(lines, last, i, i + 1)) {
                // Drop point i: the kept previous point's segment now reaches i + 1.
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

uint32_t StrokeSimplifier::removeFolds(Polylines& lines, float maxLength) const
{
    if (maxLength <= 0.0f) return 0;
    constexpr float kTurnBack = -0.5f; // cos 120 degrees
    uint32_t write = 0, removed = 0, newStart = 0;
    for (uint32_t p = 0; p < lines.count(); ++p) {
        const uint32_t begin = lines.start[p], end = lines.start[p + 1];
        lines.start[p] = newStart;
        uint32_t last = 0;
        for (uint32_t i = begin; i < end; ++i) {
            if (i > begin && i + 1 < end && lines.state[last] == kVisible &&
                lines.state[i] == kVisible) {
                const glm::vec2 a = glm::vec2(lines.points[i].window) -
                                    glm::vec2(lines.points[last].window);
                const glm::vec2 b = glm::vec2(lines.points[i + 1].window) -
                                    glm::vec2(lines.points[i].window);
                const float la = glm::length(a), lb = glm::length(b);
                if (la > 0.0f && lb > 0.0f && std::min(la, lb) < maxLength &&
                    glm::dot(a, b) < kTurnBack * la * lb) {
                    ++removed;
                    continue;
                }
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

} // namespace nprgl::styles::strokes
