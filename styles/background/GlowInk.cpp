#include "styles/background/GlowInk.h"

#include "common/Log.h"
#include "styles/shading/ShadingCommon.h"

#include <string>

namespace nprgl::styles {

namespace {

// What the program would add, and the ink standing for it on the page.
// No vertex shader: the fixed-function vertex stage computes, from the program's own state,
// the lit colour (every light, materials set per vertex), the texture coordinates (texgen,
// texture matrix) and the fog coordinate, as for the program's draw. The fragment shader
// then does what the fixed pipeline would: GL_MODULATE by unit 0's texture, the fog.
// (After ShadingCommon::fogFactorFunction().)
const char* kFragmentCommon = R"(
uniform sampler2D tex;
uniform bool textured;
uniform bool sourceAlpha;
uniform float fogMode; // the program's, as ShadingCommon::fogModeCode (gl_Fog has the rest)
// The program's fragment: its colour, texture and fog (additive effects fade into a black
// fog with distance: they add nothing far away).
vec4 fragment()
{
    vec4 c = textured ? gl_Color * texture2DProj(tex, gl_TexCoord[0]) : gl_Color;
    vec3 range = vec3(gl_Fog.start, gl_Fog.end, gl_Fog.density);
    float f = fogFactor(fogMode, abs(gl_FogFragCoord), range);
    return vec4(mix(gl_Fog.color.rgb, c.rgb, f), c.a);
}
vec3 added()
{
    vec4 c = fragment();
    return clamp(sourceAlpha ? c.rgb * c.a : c.rgb, 0.0, 1.0);
}
vec3 ink(vec3 a) { return vec3(1.0 - max(max(a.r, a.g), a.b)) + a; }
)";

// Ink alone, multiplied in (GL_DST_COLOR, GL_ZERO). Each main's alpha is the program's
// fragment's, which its alpha test (still on) keeps or drops, as glyphs drawn as glowing text
// keep their shapes; blending leaves the framebuffer's alpha as it was.
const char* kInkMain = R"(
void main() { gl_FragColor = vec4(ink(added()), fragment().a); }
)";

// With dual-source blending (GL_ONE_MINUS_DST_COLOR, GL_SRC1_COLOR) the page decides per
// pixel: dst' = added * (1 - dst) + dst * ink. On the light page that is the ink; on a dark
// surface of the scene it is nearly the program's own addition (a torch on a dark wall
// still glows).
const char* kDualMain = R"(
out vec4 fragColor;
out vec4 inkColour;
void main()
{
    vec3 a = added();
    fragColor = vec4(a, fragment().a);
    inkColour = vec4(ink(a), 1.0);
}
)";

} // namespace

bool GlowInk::init(const GlFunctions& gl, std::string& error)
{
    const std::string common = std::string(ShadingCommon::fogFactorFunction()) + kFragmentCommon;
    const std::string f120 = "#version 120\n" + common + kInkMain;
    const std::string f130 = "#version 130\n" + common + kDualMain;
    std::string dualError;
    mDual = gl.BindFragDataLocationIndexed &&
            mProgram.build(gl, nullptr, f130.c_str(), dualError, "inkColour");
    if (!mDual) {
        // Ink everywhere then: glows over the scene's dark parts darken instead of lighting.
        NPRGL_INFO("glow ink: %s; glows are ink everywhere, also over dark surfaces",
                   gl.BindFragDataLocationIndexed ? ("no dual-source program: " + dualError).c_str()
                                                  : "the driver has no dual-source blending");
        if (!mProgram.build(gl, nullptr, f120.c_str(), error)) return false;
    }
    mTextured = mProgram.uniform(gl, "textured");
    mSourceAlpha = mProgram.uniform(gl, "sourceAlpha");
    mFogMode = mProgram.uniform(gl, "fogMode");
    gl.UseProgram(mProgram.id());
    gl.Uniform1i(mProgram.uniform(gl, "tex"), 0);
    gl.UseProgram(0);
    return true;
}

void GlowInk::begin(const GlFunctions& gl, bool textured, bool sourceAlpha, GLenum fogMode)
{
    gl.UseProgram(mProgram.id());
    gl.Uniform1f(mFogMode, ShadingCommon::fogModeCode(fogMode));
    gl.Uniform1i(mTextured, textured ? 1 : 0);
    gl.Uniform1i(mSourceAlpha, sourceAlpha ? 1 : 0);
    gl.Enable(GL_BLEND);
    gl.BlendEquation(GL_FUNC_ADD);
    if (mDual) gl.BlendFuncSeparate(GL_ONE_MINUS_DST_COLOR, GL_SRC1_COLOR, GL_ZERO, GL_ONE);
    else gl.BlendFuncSeparate(GL_DST_COLOR, GL_ZERO, GL_ZERO, GL_ONE);
}

void GlowInk::end(const GlFunctions& gl) { gl.UseProgram(0); }

void GlowInk::shutdown(const GlFunctions& gl) { mProgram.destroy(gl); }

} // namespace nprgl::styles
