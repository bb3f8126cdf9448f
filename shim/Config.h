#pragma once

// Config: what a context of this process is asked to do (style chain and values, screenshots),
// built once at start-up and handed to each context.

#include "common/FrameSet.h"
#include "styles/StyleSettings.h"

#include <string>

namespace nprgl {

struct Config {
    StyleSettings style;
    bool screenshots = false;
    FrameSet screenshotFrames;
    std::string screenshotDir;
    std::string programName;

    // Parses NPRGL_STYLE, NPRGL_CONFIG and NPRGL_SCREENSHOT. Bad values are reported and
    // replaced by safe ones (style none, no screenshots); the program runs on.
    static Config fromEnvironment();

    // The process's configuration: the one given to use() or, when nothing was, the
    // environment's, read (and reported) when the first context becomes current (a program
    // that never uses GL never reads it and never hears from us).
    static const Config& process();
    // In-process callers (the replayer, tests) hand their own before any context exists;
    // false (and nothing changes) once process() has been read.
    static bool use(Config config);
};

} // namespace nprgl
