#pragma once

// The analytic truth of demo_shapes by CPU ray casting, independent of GL.

#include "Shapes.h"

#include <cstdint>
#include <vector>

namespace shapes {

// Per pixel (top row first): the id of the nearest shape (index + 1, 0 = background) and its
// eye-space depth (distance along -z; infinity for the background).
struct TruthFrame {
    int width = 0;
    int height = 0;
    std::vector<int> ids;
    std::vector<double> depths;
};

// Casts one ray through each pixel centre with the camera GL uses.
TruthFrame castRays(const std::vector<Shape>& shapes, const Camera& camera, int width,
                    int height);

// Silhouette pixels (1) on the occluding side: a pixel whose 4-neighbour shows another id
// farther away (or the background), or the same object more than relativeJump farther where
// that step in inverse depth is over 3x the steps beside it (an occluding contour inside one
// object, e.g. a torus's inner rim, but not a face seen at a grazing angle).
std::vector<uint8_t> silhouettes(const TruthFrame& frame, double relativeJump);

// Distance along the unit ray to the nearest hit of one shape in its own frame, or a negative
// value for a miss. Exposed for the tests of the intersection routines.
double intersect(const Shape& shape, Vec3 origin, Vec3 direction);

} // namespace shapes
