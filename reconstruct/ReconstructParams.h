#pragma once

namespace nprgl::reconstruct {

struct ReconstructParams {
    // Corners closer than this fraction of the object's bounding-box diagonal weld into one
    // vertex. Programs compute a seam vertex twice (sin/cos of 0 and 2*pi, two batches), so
    // exact equality would leave cracks; 1e-5 is far below any real edge length.
    float weldTolerance = 1e-5f;
    // How far (x bounding-box diagonal at the build) two welded corners may drift apart in an
    // animated update and still share their vertex: skinning gives a seam's two copies of a
    // vertex slightly different weights, and the topology must not change for that.
    float updateTolerance = 1e-2f;
    // An interior edge is a crease when the cosine of the angle between its two face normals
    // is below this (thesis §4.2: n1·n2 < t). 0.5 = normals more than 60 degrees apart: the
    // box edges of a cube (90) are creases, a 16-segment sphere (22.5) has none.
    float creaseCosine = 0.5f;
};

} // namespace nprgl::reconstruct
