#pragma once

// GlowInk: additive glows (fire, flares, particles) drawn as coloured ink on a light page.

#include "styles/ShaderProgram.h"

namespace nprgl::styles {

// Added to a page of paper, a glow saturates to white and vanishes. Around such a draw of
// the program's (left as it draws it: GL_ONE or GL_SRC_ALPHA onto GL_ONE), this program and
// a multiplying blend turn what it would add, c, into the page darkened towards c's hue by
// c's strength: page * (1 - max(c) + c). Black adds nothing and changes nothing; a bright
// orange flame becomes orange ink. Where the driver blends two source colours (GL 3.3's
// dual-source blending), the pixel's own lightness weighs ink against addition, so over the
// dark parts of a scene a glow still lights up; without it, ink everywhere. Fixed-function
// draws only: the fixed-function vertex stage lights, texgens and fogs them as the program's
// draw; the fragment shader modulates by unit 0's texture and applies the fog.
class GlowInk {
public:
    bool init(const GlFunctions& gl, std::string& error);
    // The caller has pushed GL_COLOR_BUFFER_BIT and checked that no program of the program's
    // is bound; end() unbinds ours.
    // fogMode: the program's (GL_LINEAR, GL_EXP, GL_EXP2), 0 when its fog is off.
    void begin(const GlFunctions& gl, bool textured, bool sourceAlpha, GLenum fogMode);
    void end(const GlFunctions& gl);
    void shutdown(const GlFunctions& gl);

private:
    ShaderProgram mProgram;
    GLint mTextured = -1, mSourceAlpha = -1, mFogMode = -1;
    bool mDual = false; // dual-source blending: ink on light pixels, light on dark ones
};

} // namespace nprgl::styles
