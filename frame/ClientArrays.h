#pragma once

#include "shim/Api.h"

#include <array>
#include <cstdint>

namespace nprgl {

// Identifies a client vertex array: the fixed-function ones, one per texture unit, one per
// generic attribute.
enum ArraySlot : uint8_t {
    kVertexArray,
    kNormalArray,
    kColorArray,
    kSecondaryColorArray,
    kFogCoordArray,
    kIndexArray,
    kEdgeFlagArray,
    kTexCoordArray0,
    kAttribArray0 = kTexCoordArray0 + 8,
    kArraySlotCount = kAttribArray0 + 16,
};

// The client-array state the recorder must know to copy the memory a draw reads.
struct ClientArray {
    bool enabled = false;
    bool inBuffer = false; // pointer is an offset into a buffer object: nothing to copy
    GLint size = 4;
    GLenum type = GL_FLOAT;
    GLsizei stride = 0;
    const uint8_t* pointer = nullptr;

    size_t elementBytes() const;
    size_t effectiveStride() const;
};

struct ClientArrayState {
    std::array<ClientArray, kArraySlotCount> arrays{};
    GLuint arrayBuffer = 0;
    GLuint elementBuffer = 0;
    GLuint unpackBuffer = 0;
    int clientActiveTexture = 0;
};

// The slot of a glEnableClientState/glDisableClientState array name, or -1.
int arraySlotForCap(GLenum cap, int clientActiveTexture);
// The slot a recorded pointer call sets (its opcode; attribIndex >= 0: glVertexAttribPointer's
// index, as the decoder hands it to a sink's clientPointer), or -1.
int arraySlotForPointerCall(uint16_t opcode, int attribIndex, int clientActiveTexture);

} // namespace nprgl
