#pragma once

// Opcodes of the Stream: one per GL command (generated: GL 1.0-2.1 in registry order, then the
// rest) plus the pseudo-calls the recorder adds (frame end, client-array data, batch
// references, the frame's calls that were not captured, the name a created object got).

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
    if (opcode == op::kUncaptured) return "Uncaptured";
    if (opcode == op::kCreated) return "Created";
    return nullptr;
}
} // namespace nprgl
