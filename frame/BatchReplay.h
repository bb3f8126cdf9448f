#pragma once

// replayBatch: runs the recorded calls of one glBegin..glEnd (held back while nprgl decided
// whether it was a pass over held geometry) through the driver.

#include <cstddef>
#include <cstdint>

namespace nprgl {

// Runs the calls in data (as the recorder wrote them: glBegin, the vertices and their
// attributes, the client-array data glArrayElement reads) through the driver, up to but not
// including glEnd, which the caller issues. False, with the rest not run, when a call cannot
// be decoded (the batch is then incomplete; glEnd still closes it).
bool replayBatch(const uint8_t* data, size_t size);

} // namespace nprgl
