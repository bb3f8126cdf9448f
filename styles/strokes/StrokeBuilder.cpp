#include "styles/strokes/StrokeBuilder.h"

#include <algorithm>
#include <cmath>

namespace nprgl::styles::strokes {

namespace {

constexpr float kTinyPixels = 1e-3f; // shorter segments have no reliable direction

glm::vec2 screenDelta(const Polylines& lines, uint32_t segment)
{
    return glm::vec2(lines.points[segment + 1].window) - glm::vec2(lines.points[segment].window);
}

} // namespace

void StrokeBuilder::build(const Polylines& lines, const Options& options, Polylines& strokes)
{
    strokes.clear();
    const float cosLimit = std::cos(glm::radians(std::clamp(options.maxAngle, 0.0f, 180.0f)));
    for (uint32_t p = 0; p < lines.count(); ++p) {
        const uint32_t begin = lines.start[p], end = lines.start[p + 1];
        if (end - begin < 2) continue;
        const uint32_t segments = end - begin - 1;
        const bool closed = lines.closed[p] != 0;
        // Break flags in chain order: hidden segments, and sharp turns between visible ones.
        mBreak.assign(segments, 0);
        mLength.resize(segments);
        bool anyBreak = false;
        glm::vec2 direction(0.0f);
        bool haveDirection = false;
        if (closed) {
            // The turn at the seam compares with the chain's last usable direction.
            for (uint32_t k = segments; k-- > 0;) {
                const glm::vec2 d = screenDelta(lines, begin + k);
                if (lines.state[begin + k] != kVisible) break;
                if (glm::length(d) > kTinyPixels) {
                    direction = glm::normalize(d);
                    haveDirection = true;
                    break;
                }
            }
        }
        for (uint32_t k = 0; k < segments; ++k) {
            const uint32_t s = begin + k;
            const glm::vec2 d = screenDelta(lines, s);
            mLength[k] = glm::length(d);
            if (lines.state[s] != kVisible) {
                mBreak[k] = 1;
                anyBreak = true;
                haveDirection = false;
                continue;
            }
            if (mLength[k] > kTinyPixels) {
                const glm::vec2 unit = d / mLength[k];
                if (haveDirection && glm::dot(unit, direction) < cosLimit) {
                    mBreak[k] = 1;
                    anyBreak = true;
                }
                direction = unit;
                haveDirection = true;
            }
            if (k == 0 && !closed) mBreak[k] = 1;
            if (k > 0 && lines.state[s - 1] != kVisible) mBreak[k] = 1;
        }
        if (closed && lines.state[begin + segments - 1] != kVisible) mBreak[0] = 1;
        // Drawing order: a closed chain starts at its first break (if any).
        uint32_t rotate = 0;
        if (closed && anyBreak) {
            while (!mBreak[rotate]) ++rotate;
        }
        mOrder.resize(segments);
        for (uint32_t k = 0; k < segments; ++k) mOrder[k] = (k + rotate) % segments;
        const bool loop = closed && !anyBreak;
        mBegin = begin;
        mMinLength = options.minLength;
        uint32_t runStart = 0;
        for (uint32_t k = 0; k <= segments; ++k) {
            const bool atEnd = k == segments;
            const uint32_t seg = atEnd ? 0 : mOrder[k];
            if (!atEnd && lines.state[begin + seg] == kVisible && !(k > runStart && mBreak[seg])) {
                continue;
            }
            if (k > runStart) emitRun(lines, options, runStart, k - runStart, loop, strokes);
            runStart = (!atEnd && lines.state[begin + seg] == kVisible) ? k : k + 1;
        }
    }
}

void StrokeBuilder::emitRun(const Polylines& lines, const Options& options, uint32_t first,
                            uint32_t count, bool closedLoop, Polylines& strokes)
{
    // first/count index mOrder; the segment's point index is begin + mOrder[k].
    float total = 0.0f;
    for (uint32_t k = first; k < first + count; ++k) total += mLength[mOrder[k]];
    uint32_t pieces = 1;
    if (options.maxSegments > 0)
        pieces = std::max(pieces, (count + options.maxSegments - 1) / options.maxSegments);
    if (options.maxLength > 0.0f)
        pieces = std::max(pieces, uint32_t(std::ceil(total / options.maxLength)));
    pieces = std::min(pieces, count);
    // Equal shares by length (or by count when only the segment limit applies).
    const bool byLength = options.maxLength > 0.0f && total > 0.0f;
    uint32_t pieceStart = first;
    float done = 0.0f;
    for (uint32_t piece = 1; piece <= pieces; ++piece) {
        uint32_t pieceEnd = first + count;
        if (piece < pieces) {
            if (byLength) {
                const float target = total * float(piece) / float(pieces);
                pieceEnd = pieceStart;
                while (pieceEnd < first + count && done + 0.5f * mLength[mOrder[pieceEnd]] < target)
                    done += mLength[mOrder[pieceEnd++]];
                // At least one segment, while the run has one left: earlier pieces may have
                // taken them all (short segments before a long one).
                if (pieceEnd == pieceStart && pieceEnd < first + count)
                    done += mLength[mOrder[pieceEnd++]];
            } else {
                pieceEnd = first + uint32_t(uint64_t(count) * piece / pieces);
            }
            if (options.maxSegments > 0)
                pieceEnd = std::min(pieceEnd, pieceStart + options.maxSegments);
        }
        if (pieceEnd <= pieceStart) continue;
        emitStroke(lines, pieceStart, pieceEnd - pieceStart, closedLoop && pieces == 1, strokes);
        for (uint32_t k = pieceStart; k < pieceEnd && !byLength; ++k) done += mLength[mOrder[k]];
        pieceStart = pieceEnd;
    }
}

void StrokeBuilder::emitStroke(const Polylines& lines, uint32_t first, uint32_t count,
                               bool closed, Polylines& strokes)
{
    // mOrder entries are segment offsets from the polyline's first point.
    const uint32_t begin = mBegin;
    float length = 0.0f;
    for (uint32_t k = first; k < first + count; ++k) length += mLength[mOrder[k]];
    const uint32_t mark = uint32_t(strokes.points.size());
    for (uint32_t k = first; k < first + count; ++k) {
        const uint32_t s = begin + mOrder[k];
        strokes.addPoint(lines.points[s], lines.edge[s], kVisible);
    }
    const uint32_t lastSegment = begin + mOrder[first + count - 1];
    strokes.addPoint(lines.points[lastSegment + 1], 0, kUnknown);
    if (length < mMinLength) {
        // Too short to draw: forget it.
        strokes.points.resize(mark);
        strokes.edge.resize(mark);
        strokes.state.resize(mark);
        return;
    }
    strokes.endPolyline(closed);
}

} // namespace nprgl::styles::strokes
