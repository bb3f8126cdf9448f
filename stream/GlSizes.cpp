#include "stream/GlSizes.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cstdint>

namespace nprgl {

size_t pnameCount(uint32_t pname)
{
    switch (pname) {
    case GL_AMBIENT:
    case GL_DIFFUSE:
    case GL_SPECULAR:
    case GL_POSITION:
    case GL_EMISSION:
    case GL_AMBIENT_AND_DIFFUSE:
    case GL_LIGHT_MODEL_AMBIENT:
    case GL_FOG_COLOR:
    case GL_TEXTURE_BORDER_COLOR:
    case GL_TEXTURE_ENV_COLOR:
    case GL_OBJECT_PLANE:
    case GL_EYE_PLANE:
        return 4;
    case GL_SPOT_DIRECTION:
    case GL_COLOR_INDEXES:
    case GL_POINT_DISTANCE_ATTENUATION:
        return 3;
    default:
        return 1;
    }
}

size_t callListsBytes(int n, uint32_t type)
{
    if (n <= 0) return 0;
    switch (type) {
    case GL_BYTE:
    case GL_UNSIGNED_BYTE: return size_t(n);
    case GL_SHORT:
    case GL_UNSIGNED_SHORT:
    case GL_2_BYTES: return size_t(n) * 2;
    case GL_3_BYTES: return size_t(n) * 3;
    case GL_INT:
    case GL_UNSIGNED_INT:
    case GL_FLOAT:
    case GL_4_BYTES: return size_t(n) * 4;
    default: return 0;
    }
}

size_t indexBytes(uint32_t type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE: return 1;
    case GL_UNSIGNED_SHORT: return 2;
    case GL_UNSIGNED_INT: return 4;
    default: return 0;
    }
}

namespace {

size_t componentBytes(uint32_t type)
{
    switch (type) {
    case GL_BYTE:
    case GL_UNSIGNED_BYTE: return 1;
    case GL_SHORT:
    case GL_UNSIGNED_SHORT:
    case GL_HALF_FLOAT: return 2;
    case GL_INT:
    case GL_UNSIGNED_INT:
    case GL_FLOAT: return 4;
    case GL_DOUBLE: return 8;
    default: return 0;
    }
}

size_t formatComponents(uint32_t format)
{
    switch (format) {
    case GL_COLOR_INDEX:
    case GL_STENCIL_INDEX:
    case GL_DEPTH_COMPONENT:
    case GL_RED:
    case GL_GREEN:
    case GL_BLUE:
    case GL_ALPHA:
    case GL_LUMINANCE:
    case GL_INTENSITY:
    case GL_RED_INTEGER:
    case GL_GREEN_INTEGER:
    case GL_BLUE_INTEGER:
    case GL_ALPHA_INTEGER: return 1;
    case GL_LUMINANCE_ALPHA:
    case GL_RG:
    case GL_RG_INTEGER:
    case GL_DEPTH_STENCIL: return 2;
    case GL_RGB:
    case GL_BGR:
    case GL_RGB_INTEGER:
    case GL_BGR_INTEGER: return 3;
    case GL_RGBA:
    case GL_BGRA:
    case GL_RGBA_INTEGER:
    case GL_BGRA_INTEGER: return 4;
    default: return 0;
    }
}

// Bytes per pixel for packed types, 0 when the type is not packed.
size_t packedPixelBytes(uint32_t type)
{
    switch (type) {
    case GL_UNSIGNED_BYTE_3_3_2:
    case GL_UNSIGNED_BYTE_2_3_3_REV: return 1;
    case GL_UNSIGNED_SHORT_5_6_5:
    case GL_UNSIGNED_SHORT_5_6_5_REV:
    case GL_UNSIGNED_SHORT_4_4_4_4:
    case GL_UNSIGNED_SHORT_4_4_4_4_REV:
    case GL_UNSIGNED_SHORT_5_5_5_1:
    case GL_UNSIGNED_SHORT_1_5_5_5_REV: return 2;
    case GL_UNSIGNED_INT_8_8_8_8:
    case GL_UNSIGNED_INT_8_8_8_8_REV:
    case GL_UNSIGNED_INT_10_10_10_2:
    case GL_UNSIGNED_INT_2_10_10_10_REV:
    case GL_UNSIGNED_INT_24_8: return 4;
    default: return 0;
    }
}

} // namespace

size_t imageBytes(uint32_t format, uint32_t type, int width, int height, int depth,
                  const UnpackState& unpack)
{
    if (width <= 0 || height <= 0 || depth <= 0) return 0;
    // The driver refuses negative unpack values; any product past 2^48 is no real image
    // (and would wrap): both are invalid here.
    if (unpack.rowLength < 0 || unpack.imageHeight < 0 || unpack.skipPixels < 0 ||
        unpack.skipRows < 0 || unpack.skipImages < 0) {
        return 0;
    }
    // 64-bit arithmetic that notes any overflow (a product past 2^64 is no real image
    // either); no 128-bit type, which 32-bit targets lack.
    bool overflow = false;
    auto mul = [&](uint64_t a, uint64_t b) {
        uint64_t r = 0;
        overflow |= __builtin_mul_overflow(a, b, &r);
        return r;
    };
    auto add = [&](uint64_t a, uint64_t b) {
        uint64_t r = 0;
        overflow |= __builtin_add_overflow(a, b, &r);
        return r;
    };
    const uint64_t alignment = unpack.alignment > 0 ? uint64_t(unpack.alignment) : 1;
    const uint64_t rowPixels = uint64_t(unpack.rowLength > 0 ? unpack.rowLength : width);
    const uint64_t imageRows = uint64_t(unpack.imageHeight > 0 ? unpack.imageHeight : height);
    auto alignUp = [&](uint64_t v) { return add(v, alignment - 1) / alignment * alignment; };
    uint64_t total = 0;
    if (type == GL_BITMAP) {
        const uint64_t rowBytes = alignUp((rowPixels + 7) / 8);
        const uint64_t firstRowBytes = (uint64_t(unpack.skipPixels) + uint64_t(width) + 7) / 8;
        total = add(mul(uint64_t(unpack.skipRows) + uint64_t(height) - 1, rowBytes),
                    firstRowBytes);
    } else {
        size_t pixelBytes = packedPixelBytes(type);
        if (!pixelBytes) pixelBytes = formatComponents(format) * componentBytes(type);
        if (!pixelBytes) return 0;
        const uint64_t rowBytes = alignUp(mul(rowPixels, pixelBytes));
        const uint64_t imageBytes = mul(rowBytes, imageRows);
        total = add(add(mul(uint64_t(unpack.skipImages) + uint64_t(depth) - 1, imageBytes),
                        mul(uint64_t(unpack.skipRows) + uint64_t(height) - 1, rowBytes)),
                    mul(uint64_t(unpack.skipPixels) + uint64_t(width), pixelBytes));
    }
    // Past 2^48, or past what this process can address (a 32-bit one), it is invalid too.
    constexpr uint64_t limit = std::min<uint64_t>(uint64_t(1) << 48, SIZE_MAX);
    if (overflow || total > limit) return 0;
    return size_t(total);
}

size_t arrayElementBytes(int size, uint32_t type)
{
    if (size == GL_BGRA) size = 4;
    return size > 0 ? size_t(size) * componentBytes(type) : 0;
}

} // namespace nprgl
