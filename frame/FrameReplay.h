#pragma once

// FrameReplay: one frame of a context's recorded calls run again through the driver, in the
// program's own context, after the frame (the screenshot key's unstyled picture of the frame
// the styles just drew).

#include "frame/ClientArrays.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace nprgl {

class FrameReplay {
public:
    // Runs data (one frame as the Recorder kept it: every client array a draw read sent
    // whole, no batch blobs) through the driver from the program's GL state as it is now;
    // client arrays set before the frame take their data from the frame's own copies, laid
    // out as `start` (the arrays as the frame began) had them. A frame that keeps to its own
    // attribute and matrix stack entries runs between a save and a restore of all of the
    // program's state; one that pops an earlier frame's entry runs from the state it left
    // and leaves it so again, its client arrays pointed back as `end` (as it ended) has them.
    // The calls that create names are not run (the program made them already). False, with
    // nothing run, when the frame holds a call that cannot run twice in place (selection and
    // feedback modes, mapped buffers, syncs) or the attribute stacks are full; false after
    // running part of it when a call cannot be decoded.
    static bool run(const uint8_t* data, size_t size, const ClientArrayState& start,
                    const ClientArrayState& end, std::string& error);
};

} // namespace nprgl
