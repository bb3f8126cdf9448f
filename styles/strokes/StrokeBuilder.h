#pragma once

#include "styles/strokes/StrokeTypes.h"

#include <cstdint>
#include <vector>

namespace nprgl::styles::strokes {

// Thesis §4.4.6: turns classified chains into strokes an artist would draw. Hidden segments
// end a stroke; a screen-space turn sharper than maxAngle ends it (this rule first); then a
// run that is longer than maxSegments segments or maxLength pixels is cut into equal parts
// (balanced, so no stub is left at the end). A closed chain that is visible all round with
// no sharp turn stays one closed stroke; otherwise it starts at one of its breaks, so a
// stroke never ends at the chain's arbitrary seam.
class StrokeBuilder {
public:
    struct Options {
        float maxAngle = 70.0f;  // degrees; 180 = never
        uint32_t maxSegments = 0; // 0 = no limit
        float maxLength = 0.0f;   // pixels; 0 = no limit
        float minLength = 0.5f;   // shorter strokes are dropped (pixels)
    };

    void build(const Polylines& lines, const Options& options, Polylines& strokes);

private:
    void emitRun(const Polylines& lines, const Options& options, uint32_t first, uint32_t count,
                 bool closedLoop, Polylines& strokes);
    void emitStroke(const Polylines& lines, uint32_t first, uint32_t count, bool closed,
                    Polylines& strokes);

    std::vector<uint32_t> mOrder;    // segment indices of one polyline, in drawing order
    std::vector<uint8_t> mBreak;     // per entry of mOrder: a stroke must start here
    std::vector<float> mLength;      // per entry of mOrder: screen length
    uint32_t mBegin = 0; // first point of the polyline being built
    float mMinLength = 0.0f;
};

} // namespace nprgl::styles::strokes
