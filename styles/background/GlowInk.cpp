#include "styles/background/GlowInk.h"

namespace nprgl::styles {

namespace {

// GLSL 1.20: the program's fixed-function attributes and matrices, as it set them.
const char* kVertex = R"(#version 120
varying vec4 colour;
varying vec2 uv;
uniform bool material;
void main()
{
    gl_Position = ftransform();
    colour = material ? gl_FrontMaterial.diffuse : gl_Color;
    uv = (gl_TextureMatrix[0] * gl_MultiTexCoord0).xy;
}
)";

const char* kFragment = R"(#version 120
varying vec4 colour;
varying vec2 uv;
uniform sampler2D tex;
uniform bool textured;
uniform bool sourceAlpha;
void main()
{
    vec4 c = textured ? colour * texture2D(tex, uv) : colour;
    vec3 added = clamp(sourceAlpha ? c.rgb * c.a : c.rgb, 0.0, 1.0);
    float strength = max(max(added.r, added.g), added.b);
    gl_FragColor = vec4(vec3(1.0 - strength) + added, 1.0);
}
)";

// With dual-source blending (GL_ONE_MINUS_DST_COLOR, GL_SRC1_COLOR) the page decides per
// pixel: dst' = added * (1 - dst) + dst * ink. On the light page that is the ink; on a dark
// surface of the scene it is nearly the program's own addition (a torch on a dark wall
// still glows).
const char* kDualVertex = R"(#version 130
out vec4 colour;
out vec2 uv;
uniform bool material;
void main()
{
    gl_Position = ftransform();
    colour = material ? gl_FrontMaterial.diffuse : gl_Color;
    uv = (gl_TextureMatrix[0] * gl_MultiTexCoord0).xy;
}
)";

const char* kDualFragment = R"(#version 130
in vec4 colour;
in vec2 uv;
uniform sampler2D tex;
uniform bool textured;
uniform bool sourceAlpha;
out vec4 fragColor;
out vec4 inkColour;
void main()
{
    vec4 c = textured ? colour * texture(tex, uv) : colour;
    vec3 added = clamp(sourceAlpha ? c.rgb * c.a : c.rgb, 0.0, 1.0);
    float strength = max(max(added.r, added.g), added.b);
    fragColor = vec4(added, 0.0);
    inkColour = vec4(vec3(1.0 - strength) + added, 1.0);
}
)";

} // namespace

bool GlowInk::init(const GlFunctions& gl, std::string& error)
{
    std::string dualError;
    mDual = gl.BindFragDataLocationIndexed &&
            mProgram.build(gl, kDualVertex, kDualFragment, dualError, "inkColour");
    if (!mDual && !mProgram.build(gl, kVertex, kFragment, error)) return false;
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
