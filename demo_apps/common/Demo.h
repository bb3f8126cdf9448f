#pragma once

#include "Scene.h"

namespace demo {

// Entry point for apps that link libOSMesa and libGL: parses options, then runs the scene.
int run(int argc, char** argv, const char* shortName, Scene& scene);

// Sets a perspective projection like gluPerspective, without depending on GLU.
void setPerspective(double fovYDegrees, double aspect, double zNear, double zFar);

} // namespace demo
