#pragma once

#include "shim/Api.h"

namespace nprgl {

// Points every GL slot of dispatch at its recording function.
void installRecording(GlDispatch& dispatch);
// Points the draw and vertex slots (glBegin/glEnd, glVertex*, glDraw*, glRect*...) at
// functions that record without calling the driver: for draws the compositor re-draws.
void installHeldRecording(GlDispatch& dispatch);

} // namespace nprgl
