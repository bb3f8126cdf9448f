#pragma once
// GL facts the tracker's parts share: blending that changes pixels, polygonal modes, list ids.

#include <GL/gl.h>

#include <cstdint>
#include <cstring>

namespace nprgl::tracker {

// The reason for a list left for the blending inside it.
inline constexpr const char* kListBlendsLeft =
    "display lists that blend inside other than by GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA "
    "(shadows, effects)";

// Blending that changes a pixel: GL_BLEND on, with functions other than GL_ONE, GL_ZERO (the
// defaults, which replace what is behind: trigger-rally leaves GL_BLEND on all frame and draws
// its opaque parts so).
inline bool changesPixels(bool blend, GLenum src, GLenum dst)
{
    return blend && !(src == GL_ONE && dst == GL_ZERO);
}

// Blending by the fragment's alpha: a translucent surface, which the styles draw after the
// opaque scene with the program's blending.
inline bool byAlpha(bool blend, GLenum src, GLenum dst)
{
    return blend && src == GL_SRC_ALPHA && dst == GL_ONE_MINUS_SRC_ALPHA;
}

// Entry i of glCallLists' array of list ids of `type`.
inline GLuint listId(GLenum type, const uint8_t* p, GLsizei i)
{
    switch (type) {
    case GL_BYTE: return GLuint(GLint(reinterpret_cast<const int8_t*>(p)[i]));
    case GL_UNSIGNED_BYTE: return p[i];
    case GL_SHORT: { int16_t v; std::memcpy(&v, p + 2 * i, 2); return GLuint(GLint(v)); }
    case GL_UNSIGNED_SHORT: { uint16_t v; std::memcpy(&v, p + 2 * i, 2); return v; }
    case GL_INT:
    case GL_UNSIGNED_INT: { uint32_t v; std::memcpy(&v, p + 4 * i, 4); return v; }
    case GL_FLOAT: { float v; std::memcpy(&v, p + 4 * i, 4); return GLuint(v); }
    case GL_2_BYTES: return GLuint(p[2 * i]) * 256 + p[2 * i + 1];
    case GL_3_BYTES: return (GLuint(p[3 * i]) << 16) + (GLuint(p[3 * i + 1]) << 8) + p[3 * i + 2];
    case GL_4_BYTES:
        return (GLuint(p[4 * i]) << 24) + (GLuint(p[4 * i + 1]) << 16) +
               (GLuint(p[4 * i + 2]) << 8) + p[4 * i + 3];
    default: return 0;
    }
}

inline bool isPolygonMode(GLenum mode) { return mode >= GL_TRIANGLES && mode <= GL_POLYGON; }

} // namespace nprgl::tracker
