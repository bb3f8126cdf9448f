#pragma once

#include <cstdint>

#include <GL/gl.h> // primitive-mode constants only; nothing here calls GL

#include "reconstruct/Batch.h"

namespace nprgl::reconstruct {

// Calls emit(a, b, c) for every triangle of one primitive of `count` vertices (indices from its
// first vertex) with the winding the GL rasterises: strips alternate so that every triangle
// keeps the first one's orientation, quads split along the diagonal `cut` names, a quad strip's
// quad j is (2j, 2j+1, 2j+3, 2j+2) split along 2j-(2j+3), polygons are fans. Returns the
// number of trailing vertices that make no primitive (the GL ignores them); modes without
// triangles return `count`.
template <typename Emit>
uint32_t assembleTriangles(uint32_t mode, uint32_t count, Emit&& emit,
                           QuadCut cut = QuadCut::V0V2)
{
    switch (mode) {
    case GL_TRIANGLES:
        for (uint32_t i = 0; i + 2 < count; i += 3) emit(i, i + 1, i + 2);
        return count % 3;
    case GL_TRIANGLE_STRIP:
        if (count < 3) return count;
        for (uint32_t i = 0; i + 2 < count; ++i) {
            if (i & 1) emit(i + 1, i, i + 2);
            else emit(i, i + 1, i + 2);
        }
        return 0;
    case GL_TRIANGLE_FAN:
    case GL_POLYGON:
        if (count < 3) return count;
        for (uint32_t i = 1; i + 1 < count; ++i) emit(0, i, i + 1);
        return 0;
    case GL_QUADS:
        for (uint32_t i = 0; i + 3 < count; i += 4) {
            if (cut == QuadCut::V1V3) {
                emit(i, i + 1, i + 3);
                emit(i + 1, i + 2, i + 3);
            } else {
                emit(i, i + 1, i + 2);
                emit(i, i + 2, i + 3);
            }
        }
        return count % 4;
    case GL_QUAD_STRIP:
        if (count < 4) return count;
        for (uint32_t i = 0; i + 3 < count; i += 2) {
            emit(i, i + 1, i + 3);
            emit(i, i + 3, i + 2);
        }
        return count % 2;
    default:
        return count;
    }
}

} // namespace nprgl::reconstruct
