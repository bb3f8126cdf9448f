#pragma once

#include "styles/strokes/StrokeTypes.h"

namespace nprgl::styles::strokes {

// Thesis §4.4.5: the visibility refinement leaves runs of collinear pieces; two neighbouring
// visible segments that are exactly collinear (pieces of one mesh edge, or edges whose
// object-space directions agree to float precision) become one. Nearly collinear pairs are
// kept: merging them would flatten the small turns a drawing needs.
class StrokeSimplifier {
public:
    // In place; returns the number of points removed.
    uint32_t simplify(Polylines& lines) const;
    // Beyond the thesis (its §4.4.8 names the artefact): a triangle mesh's silhouette can
    // fold back on itself for a few pixels (a spike where it passes a pole, or a zig-zag
    // over thin triangles). A visible point where the path turns back by more than 120
    // degrees, next to a screen segment shorter than maxLength pixels, is removed. In place;
    // returns the number of points removed.
    uint32_t removeFolds(Polylines& lines, float maxLength) const;
};

} // namespace nprgl::styles::strokes
