#pragma once

// LeftState: the draw states a rule (leave_state=) leaves as the program draws them.

#include <cstdint>

namespace nprgl {

enum LeftState : uint32_t {
    kLeaveTranslucent = 1u << 0, // blended by its alpha (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA)
    kLeaveCutout = 1u << 1,      // the alpha test on
    kLeaveDecal = 1u << 2,       // GL_POLYGON_OFFSET_FILL on
    kLeaveBackdrop = 1u << 3,    // 3D (a perspective view) without the depth test
};

} // namespace nprgl
