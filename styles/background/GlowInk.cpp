#include "styles/background/GlowInk.h"

#include "common/Log.h"

#include <string>

namespace nprgl::styles {

namespace {

// The program's fixed-function attributes and matrices, as it set them (OUT: GLSL 1.20's
// varying or 1.30's out).
const char* kVertex = R"(
OUT vec4 colour;
OUT vec2 uv;
uniform bool material;
void main()
{
    gl_Position = ftransform();
    colour = material ? gl_FrontMaterial.diffuse : gl_Color;
    uv = (gl_TextureMatrix[0] * gl_MultiTexCoord0).xy;
}
)";

// What the program would add, and the ink standing for it on the page (IN: varying or in).
const char* kFragmentCommon = R"(
IN vec4 colour;
IN vec2 uv;
uniform sampler2D tex;
uniform bool textured;
uniform bool sourceAlpha;
vec3 added()
{
    vec4 c = textured ? colour * texture2D(tex, uv) : colour;
    return clamp(sourceAlpha ? c.rgb * c.a : c.rgb, 0.0, 1.0);
}
vec3 ink(vec3 a) { return vec3(1.0 - max(max(a.r, a.g), a.b)) + a; }
)";

// Ink alone, multiplied in (GL_DST_COLOR, GL_ZERO).
const char* kInkMain = R"(
void main() { gl_FragColor = vec4(ink(added()), 1.0); }
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
    fragColor = vec4(a, 0.0);
    inkColour = vec4(ink(a), 1.0);
}
)";

} // namespace

bool GlowInk::init(const GlFunctions& gl, std::string& error)
{
    const std::string v120 = std::string("#version 120\n#define OUT varying\n") + kVertex;
    const std::string v130 = std::string("#version 130\n#define OUT out\n") + kVertex;
    const std::string f120 =
        std::string("#version 120\n#define IN varying\n") + kFragmentCommon + kInkMain;
    const std::string f130 =
        std::string("#version 130\n#define IN in\n") + kFragmentCommon + kDualMain;
    std::string dualError;
    mDual = gl.BindFragDataLocationIndexed &&
            mProgram.build(gl, v130.c_str(), f130.c_str(), dualError, "inkColour");
    if (!mDual) {
        // Ink everywhere then: glows over the scene's dark parts darken instead of lighting.
        NPRGL_INFO("glow ink: %s; glows are ink everywhere, also over dark surfaces",
                   gl.BindFragDataLocationIndexed ? ("no dual-source program: " + dualError).c_str()
                                                  : "the driver has no dual-source blending");
        if (!mProgram.build(gl, v120.c_str(), f120.c_str(), error)) return false;
    }
    mTextured = mProgram.uniform(gl, "textured");
    mSourceAlpha = mProgram.uniform(gl, "sourceAlpha");
    mMaterial = mProgram.uniform(gl, "material");
    gl.UseProgram(mProgram.id());
    gl.Uniform1i(mProgram.uniform(gl, "tex"), 0);
    gl.UseProgram(0);
    return true;
}

void GlowInk::begin(const GlFunctions& gl, bool textured, bool sourceAlpha, bool materialColour)
{
    gl.UseProgram(mProgram.id());
    gl.Uniform1i(mTextured, textured ? 1 : 0);
    gl.Uniform1i(mSourceAlpha, sourceAlpha ? 1 : 0);
    gl.Uniform1i(mMaterial, materialColour ? 1 : 0);
    gl.Enable(GL_BLEND);
    gl.BlendEquation(GL_FUNC_ADD);
    if (mDual) gl.BlendFunc(GL_ONE_MINUS_DST_COLOR, GL_SRC1_COLOR);
    else gl.BlendFunc(GL_DST_COLOR, GL_ZERO);
}

void GlowInk::end(const GlFunctions& gl) { gl.UseProgram(0); }

void GlowInk::shutdown(const GlFunctions& gl) { mProgram.destroy(gl); }

} // namespace nprgl::styles
