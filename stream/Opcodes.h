#pragma once

// Opcodes of the Stream: one per GL 1.0-2.1 command (generated, in registry order) plus the
// pseudo-calls the recorder adds (frame end, client-array data).

#include <cstddef>
#include <cstdint>

namespace nprgl {
#include "nprgl_opcodes.inc"

inline const char* opcodeName(uint16_t opcode)
{
    if (opcode < op::kCount) return kOpcodeNames[opcode];
    if (opcode == op::kFrameEnd) return "FrameEnd";
    if (opcode == op::kArrayData) return "ArrayData";
    if (opcode == op::kBatchRef) return "BatchRef";
    return nullptr;
}
} // namespace nprgl
