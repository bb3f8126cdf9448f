#pragma once

#include "Scene.h"

namespace demo {

// Entry point for apps that link libOSMesa and libGL: parses options, then runs the scene.
int run(int argc, char** argv, const char* shortName, Scene& scene);

// Sets a perspective projection like gluPerspective, without depending on GLU.
void setPerspective(double fovYDegrees, double aspect, double zNear, double zFar);

// Pushes the projection and modelview matrices and sets a projection in window pixels (z from
// -1 to 1) with an identity modelview; the matrix mode is left at GL_MODELVIEW. The caller
// pops both.
void pushPixelProjection(int width, int height);
// The same with identity matrices (normalised device coordinates).
void pushIdentityMatrices();
// Pops what pushPixelProjection or pushIdentityMatrices pushed; leaves GL_MODELVIEW current.
void popMatrices();

// A lit sphere at the origin, one GL_TRIANGLE_STRIP per band of latitude; with
// textureRepeats > 0, texture coordinates that wrap that many times around it.
void drawSphere(float radius, int stacks, int slices, float textureRepeats = 0.0f);

// A lit torus around the z axis, one GL_QUAD_STRIP per ring. Its quads are wound clockwise
// seen from outside (the pictures of the demos that draw it, and their captures, depend on
// it; they do not cull).
void drawTorus(float major, float minor, int rings, int sides);

// Around a second pass over geometry just drawn (a multi-pass surface's shine, as multi-pass
// engines draw a surface's layers): unlit added light (GL_ONE, GL_ONE), no depth writes,
// GL_LEQUAL, a warm colour; endShinePass restores the state.
void beginShinePass();
void endShinePass();

} // namespace demo
