#pragma once

#include "common/FrameSet.h"

#include <string>
#include <string_view>

namespace nprgl {

// "frames=1,10,100;dir=out": which frames to write as PNG, and where (NPRGL_SCREENSHOT and
// the command's --screenshot, which checks it before the program starts).
struct ScreenshotSpec {
    FrameSet frames;
    std::string dir = ".";

    // On failure returns false and says why in error (without naming the variable).
    static bool parse(std::string_view text, ScreenshotSpec& out, std::string& error);
};

} // namespace nprgl
