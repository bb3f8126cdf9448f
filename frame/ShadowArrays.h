#pragma once

#include "frame/ClientArrays.h"
#include "stream/CallReader.h"

#include <cstddef>
#include <cstdint>

namespace nprgl {

// Memory standing in for a program's client arrays when its stream is replayed or
// interpreted: one region per array slot, reserved once (address space only, pages appear
// as they are written) so pointers handed out never move when more data arrives.
class ShadowArrays {
public:
    static constexpr size_t kReserve = size_t(1) << 30;

    ShadowArrays() = default;
    ~ShadowArrays();
    ShadowArrays(const ShadowArrays&) = delete;
    ShadowArrays& operator=(const ShadowArrays&) = delete;

    // The slot's region, reserved on first use; null if the address space is exhausted.
    uint8_t* base(int slot);
    // Copies bytes to [offset, offset + size) of a slot; false when out of range.
    bool write(int slot, uint64_t offset, const void* data, size_t size);
    // Decodes an ArrayData pseudo-call (its opcode already read) and applies it.
    bool apply(CallReader& r);
    // The slot whose region holds p, or -1.
    int slotOf(const void* p) const;
    // The end of the furthest bytes written to a slot: what a draw may read from its base.
    size_t size(int slot) const { return slot >= 0 && slot < kArraySlotCount ? mSize[slot] : 0; }

private:
    uint8_t* mBase[kArraySlotCount] = {};
    size_t mSize[kArraySlotCount] = {};
};

} // namespace nprgl
