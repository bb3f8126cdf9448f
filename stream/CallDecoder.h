#pragma once

// decodeCall<Sink>(reader, opcode, sink): decodes one call of the Stream (generated from the
// registry by shim/gen_codec.py) and hands it to the sink, which either replays it through a
// dispatch table (Sink::kReplays) or prints it. Unknown opcodes go to sink.pseudo().

#include "stream/CallReader.h"
#include "stream/GlSizes.h"

#include <GL/gl.h>
#include <GL/glext.h>

namespace nprgl {

#include "nprgl_decode.inc"

} // namespace nprgl
