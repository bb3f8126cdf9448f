#pragma once

#include "shim/Api.h"

namespace nprgl {

// Points every GL slot of dispatch at its recording function.
void installRecording(GlDispatch& dispatch);

} // namespace nprgl
