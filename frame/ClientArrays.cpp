#include "frame/ClientArrays.h"

#include "stream/GlSizes.h"
#include "stream/Opcodes.h"

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

int arraySlotForPointerCall(uint16_t opcode, int attribIndex, int clientActiveTexture)
{
    if (attribIndex >= 0) return attribIndex < 16 ? kAttribArray0 + attribIndex : -1;
    switch (opcode) {
    case op::glVertexPointer: return kVertexArray;
    case op::glNormalPointer: return kNormalArray;
    case op::glColorPointer: return kColorArray;
    case op::glSecondaryColorPointer: return kSecondaryColorArray;
    case op::glFogCoordPointer: return kFogCoordArray;
    case op::glIndexPointer: return kIndexArray;
    case op::glEdgeFlagPointer: return kEdgeFlagArray;
    case op::glTexCoordPointer: return arraySlotForCap(GL_TEXTURE_COORD_ARRAY, clientActiveTexture);
    default: return -1;
    }
}

} // namespace nprgl
