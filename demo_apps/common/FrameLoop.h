#pragma once

#include "GlApi.h"
#include "Options.h"
#include "Scene.h"

namespace demo {

// Opens the surface the options ask for, runs the scene's frames, saves and reports.
// Returns the process exit code.
int runFrames(const Options& options, const GlApi& gl, Scene& scene);

} // namespace demo
