#include "styles/strokes/StrokeDrawer.h"

#include "styles/ObjectNames.h"
#include "styles/textures/GlTexture.h"

#include <algorithm>
#include <cstddef>

namespace nprgl::styles::strokes {

namespace {

// position: NDC xyz + pass opacity; texcoord: arc, stroke length, side (0/1), width (px).
const char* kVertex = R"(#version 130
in vec4 position;
in vec4 texcoord;
out float opacity;
noperspective out vec4 stroke;
void main()
{
    opacity = position.w;
    stroke = texcoord;
    gl_Position = vec4(position.xyz, 1.0);
}
)";

// Soft line with round caps: coverage from the distance to the stroke's centre line (and,
// in the caps, to the end point), with a one-pixel ramp for antialiasing.
const char* kSketchy = R"(#version 130
uniform vec4 color;
uniform float feather;
in float opacity;
noperspective in vec4 stroke;
out vec4 fragColor;
void main()
{
    float halfWidth = 0.5 * stroke.w;
    float across = abs(stroke.z - 0.5) * 2.0 * (halfWidth + feather);
    float along = stroke.y < 0.0 ? 0.0
                : max(max(halfWidth - stroke.x, stroke.x - (stroke.y - halfWidth)), 0.0);
    float dist = length(vec2(across, along));
    float coverage = clamp(halfWidth - dist + 0.5, 0.0, 1.0);
    fragColor = vec4(color.rgb, color.a * opacity * coverage);
}
)";

// The stroke texture: u in [0, u1) over the first capLength pixels, the middle [u1, u2]
// repeated a whole number of times, (u2, 1] over the last capLength pixels.
const char* kTextured = R"(#version 130
uniform sampler2D strokeTexture;
uniform vec4 color;
uniform float feather;
uniform float capLength;
uniform float tileLength;
uniform float u1;
uniform float u2;
in float opacity;
noperspective in vec4 stroke;
out vec4 fragColor;
void main()
{
    float arc = stroke.x;
    float len = max(abs(stroke.y), 1e-3);
    float cap = stroke.y < 0.0 ? 0.0 : min(capLength, 0.5 * len);
    float middle = len - 2.0 * cap;
    float tiles = max(1.0, floor(middle / tileLength + 0.5));
    float tile = max(middle / tiles, 1e-3);
    float u;
    if (arc < cap) u = arc / max(cap, 1e-3) * u1;
    else if (arc > len - cap) u = u2 + (arc - (len - cap)) / max(cap, 1e-3) * (1.0 - u2);
    else u = u1 + fract((arc - cap) / tile) * (u2 - u1);
    float halfWidth = 0.5 * stroke.w;
    float v = 0.5 + (stroke.z - 0.5) * (halfWidth + feather) / max(halfWidth, 1e-3);
    // Mip level from the along-stroke rate only (the unwrapped u, so the wrap of the middle
    // picks no wrong level); across, a few pixels must still see the texture's own profile.
    float unwrapped = arc * (u2 - u1) / tile;
    vec4 texel = textureGrad(strokeTexture, vec2(u, v), vec2(dFdx(unwrapped), 0.0),
                             vec2(dFdy(unwrapped), 0.0));
    // Nothing outside the texture's height; a pixel-wide ramp at its edges.
    texel.a *= clamp((0.5 - abs(v - 0.5)) * 2.0 * halfWidth + 0.5, 0.0, 1.0);
    fragColor = vec4(color.rgb * texel.rgb, color.a * opacity * texel.a);
}
)";

constexpr float kFeather = 0.75f; // must match StrokeGeometry

} // namespace

bool StrokeDrawer::init(const GlFunctions& gl, std::string& error)
{
    if (!mSketchy.build(gl, kVertex, kSketchy, error)) return false;
    if (!mTextured.build(gl, kVertex, kTextured, error)) return false;
    ObjectNames::reserve(gl, ObjectNames::Kind::Buffer, 1, &mBuffer);
    return true;
}

void StrokeDrawer::destroy(const GlFunctions& gl)
{
    mSketchy.destroy(gl);
    mTextured.destroy(gl);
    if (mBuffer) gl.DeleteBuffers(1, &mBuffer);
    if (mTexture) gl.DeleteTextures(1, &mTexture);
    mBuffer = mTexture = 0;
    mBufferBytes = 0;
}

void StrokeDrawer::setTexture(const GlFunctions& gl, const PngImage& image)
{
    if (!mTexture) ObjectNames::reserve(gl, ObjectNames::Kind::Texture, 1, &mTexture);
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, mTexture);
    GlTexture::resetUnpack(gl);
    gl.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA,
                  GL_UNSIGNED_BYTE, image.rgba.data());
    gl.GenerateMipmap(GL_TEXTURE_2D);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
}

void StrokeDrawer::draw(const GlFunctions& gl, const std::vector<StrokeVertex>& vertices,
                        const Options& options)
{
    if (vertices.empty()) return;
    const ShaderProgram& program = options.textured && mTexture ? mTextured : mSketchy;
    gl.UseProgram(program.id());
    gl.Uniform4f(program.uniform(gl, "color"), options.color.r, options.color.g,
                 options.color.b, options.color.a);
    gl.Uniform1f(program.uniform(gl, "feather"), kFeather);
    if (&program == &mTextured) {
        gl.ActiveTexture(GL_TEXTURE0);
        gl.BindTexture(GL_TEXTURE_2D, mTexture);
        gl.Uniform1i(program.uniform(gl, "strokeTexture"), 0);
        gl.Uniform1f(program.uniform(gl, "capLength"), options.capLength);
        gl.Uniform1f(program.uniform(gl, "tileLength"), std::max(options.tileLength, 1.0f));
        gl.Uniform1f(program.uniform(gl, "u1"), options.u1);
        gl.Uniform1f(program.uniform(gl, "u2"), options.u2);
    }
    const GLsizeiptr bytes = GLsizeiptr(vertices.size() * sizeof(StrokeVertex));
    gl.BindBuffer(GL_ARRAY_BUFFER, mBuffer);
    if (bytes > mBufferBytes) {
        mBufferBytes = std::max(bytes, mBufferBytes * 2);
        gl.BufferData(GL_ARRAY_BUFFER, mBufferBytes, nullptr, GL_STREAM_DRAW);
    }
    gl.BufferSubData(GL_ARRAY_BUFFER, 0, bytes, vertices.data());
    const GLsizei stride = sizeof(StrokeVertex);
    gl.VertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, stride, nullptr);
    gl.VertexAttribPointer(3, 4, GL_FLOAT, GL_FALSE, stride,
                           reinterpret_cast<const void*>(offsetof(StrokeVertex, arc)));
    gl.EnableVertexAttribArray(0);
    gl.DisableVertexAttribArray(1);
    gl.DisableVertexAttribArray(2);
    gl.EnableVertexAttribArray(3);

    gl.Enable(GL_BLEND);
    gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    gl.Disable(GL_CULL_FACE);
    if (options.depthTest) {
        gl.Enable(GL_DEPTH_TEST);
        gl.DepthFunc(GL_LEQUAL);
    } else {
        gl.Disable(GL_DEPTH_TEST);
    }
    gl.DepthMask(GL_FALSE);
    gl.DrawArrays(GL_TRIANGLES, 0, GLsizei(vertices.size()));
    gl.DisableVertexAttribArray(0);
    gl.DisableVertexAttribArray(3);
    gl.DepthMask(GL_TRUE);
    gl.Enable(GL_DEPTH_TEST);
    gl.Disable(GL_BLEND);
}

} // namespace nprgl::styles::strokes
