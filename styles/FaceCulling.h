#pragma once

// FaceCulling: the program's face culling around the styles' draws of one object.

#include "styles/GlFunctions.h"
#include "styles/Scene.h"

namespace nprgl::styles {

// The faces the program culled are not the picture's: a plane seen from its culled side (a
// floor under a lamp, the inside of a box) is invisible in the program and must stay so in
// the styles, which draw both sides of a face otherwise. The mesh keeps the program's winding,
// so the same winding is culled in window space (which also folds in a mirroring modelview).
class FaceCulling {
public:
    // Whether the object has anything left to draw (GL_FRONT_AND_BACK culls it whole).
    static bool begin(const GlFunctions& gl, const SceneObject& object);
    // Back to the styles' baseline (no culling, counter-clockwise front faces).
    static void end(const GlFunctions& gl, const SceneObject& object);
    // The window-space winding of the faces the program shows: clockwise where it culls the
    // counter-clockwise ones (Quake III's renderer culls GL_FRONT), counter-clockwise where it
    // culls the others; where it culls nothing, the side its normals point out of.
    static GLenum shownWinding(const SceneObject& object);
};

} // namespace nprgl::styles
