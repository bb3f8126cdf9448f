#include "frame/ClientArrays.h"

#include "stream/GlSizes.h"

namespace nprgl {

size_t ClientArray::elementBytes() const { return arrayElementBytes(size, type); }

size_t ClientArray::effectiveStride() const
{
    return stride > 0 ? size_t(stride) : elementBytes();
}

int arraySlotForCap(GLenum cap, int clientActiveTexture)
{
    switch (cap) {
    case GL_VERTEX_ARRAY: return kVertexArray;
    case GL_NORMAL_ARRAY: return kNormalArray;
    case GL_COLOR_ARRAY: return kColorArray;
    case GL_SECONDARY_COLOR_ARRAY: return kSecondaryColorArray;
    case GL_FOG_COORD_ARRAY: return kFogCoordArray;
    case GL_INDEX_ARRAY: return kIndexArray;
    case GL_EDGE_FLAG_ARRAY: return kEdgeFlagArray;
    case GL_TEXTURE_COORD_ARRAY:
        return clientActiveTexture >= 0 && clientActiveTexture < 8
                   ? kTexCoordArray0 + clientActiveTexture
                   : -1;
    default: return -1;
    }
}

} // namespace nprgl
