#include "frame/ShadowArrays.h"

#include <algorithm>
#include <cstring>
#include <sys/mman.h>

namespace nprgl {

ShadowArrays::~ShadowArrays()
{
    for (uint8_t* p : mBase) {
        if (p) munmap(p, kReserve);
    }
}

uint8_t* ShadowArrays::base(int slot)
{
    if (slot < 0 || slot >= kArraySlotCount) return nullptr;
    if (!mBase[slot]) {
        void* p = mmap(nullptr, kReserve, PROT_READ | PROT_WRITE,
                       MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
        mBase[slot] = p == MAP_FAILED ? nullptr : static_cast<uint8_t*>(p);
    }
    return mBase[slot];
}

bool ShadowArrays::write(int slot, uint64_t offset, const void* data, size_t size)
{
    if (offset > kReserve || size > kReserve - offset) return false;
    uint8_t* b = base(slot);
    if (!b) return false;
    if (data && size) std::memcpy(b + offset, data, size);
    mSize[slot] = std::max<size_t>(mSize[slot], offset + size);
    return true;
}

int ShadowArrays::slotOf(const void* p) const
{
    const auto* q = static_cast<const uint8_t*>(p);
    for (int slot = 0; slot < kArraySlotCount; ++slot) {
        if (mBase[slot] && q >= mBase[slot] && q < mBase[slot] + kReserve) return slot;
    }
    return -1;
}

bool ShadowArrays::apply(CallReader& r)
{
    CallReader::Payload payload(r);
    uint8_t slot = r.get<uint8_t>();
    uint64_t offset = r.get<uint64_t>();
    size_t size = 0;
    const void* data = r.getBytes(size);
    if (!payload.finish()) return false;
    if (slot >= kArraySlotCount || !write(slot, offset, data, size)) {
        r.fail("client array data out of range");
        return false;
    }
    return true;
}

} // namespace nprgl
