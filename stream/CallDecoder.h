#pragma once

// decodeCall<Sink>(reader, opcode, sink): decodes one call of the Stream (generated from the
// registry by shim/gen_codec.py) and hands it to the sink, which either replays it through a
// dispatch table (Sink::kReplays) or prints it. Unknown opcodes go to sink.pseudo().

#include "stream/CallReader.h"
#include "stream/GlSizes.h"

#include <GL/gl.h>
#include <GL/glext.h>

#include <string>

namespace nprgl {

#include "nprgl_decode.inc"

// Decodes every call in r into the sink; an unknown opcode is an error.
template <typename Sink>
bool decodeCalls(CallReader& r, Sink& sink)
{
    while (!r.atEnd()) {
        const uint16_t opcode = r.opcode();
        if (!r.ok()) return false;
        if (!decodeCall(r, opcode, sink)) {
            if (r.ok()) r.fail("unknown opcode " + std::to_string(opcode));
            return false;
        }
    }
    return true;
}

// Runs the calls of a batch reference (its opcode already read) through the sink. The
// recorder never nests them, so a nested one is refused: a few levels of blobs that each
// refer many times to the next would otherwise run an exponential number of calls.
template <typename Sink>
bool expandBatchRef(CallReader& r, Sink& sink, int& depth)
{
    const std::vector<uint8_t>* blob = r.getBlobRef();
    if (!blob) return false;
    if (depth >= 1) {
        r.fail("batch reference inside a referenced batch");
        return false;
    }
    ++depth;
    CallReader inner(blob->data(), blob->size(), r.blobs(), r.opcodes());
    const bool ok = decodeCalls(inner, sink);
    --depth;
    if (!ok) r.fail("in a referenced batch: " + inner.error());
    return ok;
}

} // namespace nprgl
