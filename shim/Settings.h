#pragma once

#include "common/FrameSet.h"
#include "styles/StyleSettings.h"

#include <string>

namespace nprgl {

// What the environment asks of the library, read once when the first context becomes current
// (a program that never uses GL never reads it and never hears from us).
struct Settings {
    StyleSettings style;
    bool screenshots = false;
    FrameSet screenshotFrames;
    std::string screenshotDir;
    std::string programName;

    // Parses NPRGL_STYLE, NPRGL_CONFIG and NPRGL_SCREENSHOT. Bad values are reported once
    // and replaced by safe ones (style none, no screenshots); the program runs on.
    static const Settings& get();
};

} // namespace nprgl
