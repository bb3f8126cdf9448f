#include "styles/outlines/EdgesStyle.h"

#include "styles/StyleRegistry.h"
#include "styles/outlines/OutlineParams.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>

namespace nprgl::styles {

namespace {

constexpr const char* kStyle = "edges";

const char* kGeometryVertex = R"(#version 130
uniform mat4 modelview;
uniform mat4 projection;
uniform mat3 normalMatrix;
in vec3 position;
in vec3 normal;
in vec4 color;
out vec3 eyeNormal;
out float viewDepth;
out vec4 baseColor;
void main()
{
    vec4 eye = modelview * vec4(position, 1.0);
    eyeNormal = normalMatrix * normal;
    viewDepth = -eye.z / eye.w;
    baseColor = color;
    gl_Position = projection * eye;
}
)";

// Target 0: view depth, object id, the colour packed exactly into one float, coverage.
// Target 1: the unit eye normal facing the viewer. An orthographic view may put the eye
// anywhere, so there the depth is measured from one depth range in front of the near plane
// (relative jumps are then relative to the range).
const char* kGeometryFragment = R"(#version 130
uniform float objectId;
uniform bool orthographic;
uniform float depthRange;
in vec3 eyeNormal;
in float viewDepth;
in vec4 baseColor;
void main()
{
    vec3 n = normalize(eyeNormal);
    if (!gl_FrontFacing) n = -n;
    vec3 c = floor(clamp(baseColor.rgb, 0.0, 1.0) * 255.0 + 0.5);
    float z = orthographic ? (1.0 + gl_FragCoord.z) * depthRange : max(viewDepth, 1e-6);
    gl_FragData[0] = vec4(z, objectId, c.r * 65536.0 + c.g * 256.0 + c.b,
                          1.0);
    gl_FragData[1] = vec4(n, 0.0);
}
)";

const char* kFullscreenVertex = R"(#version 130
in vec3 position;
void main() { gl_Position = vec4(position.xy, 0.0, 1.0); }
)";

// The edge operator: first-order differences between each pixel and its four neighbours
// (a cross-shaped relative of Sobel that marks both sides of a discontinuity, so the marked
// band is centred on the true edge). Silhouettes: a jump of view depth relative to the
// nearer depth (5% matters as much far away as near), or object against background.
// Creases: normals further apart than the crease angle. Material edges: another object id or
// colour at continuous depth. Alpha keeps the window depth of the near side.
const char* kDetectFragment = R"(#version 130
uniform sampler2D attributes;
uniform sampler2D normals;
uniform sampler2D depth;
uniform ivec2 size;
uniform float depthThreshold;
uniform float creaseCosine;
uniform float colourThreshold;
out vec4 fragColor;

vec3 unpackColour(float code)
{
    float r = floor(code / 65536.0);
    float g = floor((code - r * 65536.0) / 256.0);
    return vec3(r, g, code - r * 65536.0 - g * 256.0) / 255.0;
}

void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 c = texelFetch(attributes, p, 0);
    vec3 n = texelFetch(normals, p, 0).xyz;
    vec3 colour = unpackColour(c.z);
    float nearest = texelFetch(depth, p, 0).r;
    vec3 found = vec3(0.0);
    ivec2 offsets[4] = ivec2[4](ivec2(1, 0), ivec2(-1, 0), ivec2(0, 1), ivec2(0, -1));
    for (int k = 0; k < 4; ++k) {
        ivec2 q = p + offsets[k];
        if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, size))) continue;
        vec4 s = texelFetch(attributes, q, 0);
        if (c.w == 0.0 && s.w == 0.0) continue;
        if (c.w == 0.0 || s.w == 0.0 || abs(s.x - c.x) > depthThreshold * min(s.x, c.x)) {
            found.r = 1.0;
            nearest = min(nearest, texelFetch(depth, q, 0).r);
        } else if (s.y != c.y || any(greaterThan(abs(unpackColour(s.z) - colour),
                                                 vec3(colourThreshold)))) {
            found.b = 1.0;
        } else if (dot(n, texelFetch(normals, q, 0).xyz) < creaseCosine) {
            found.g = 1.0;
        }
    }
    fragColor = vec4(found, found.r + found.g + found.b > 0.0 ? nearest : 1.0);
}
)";

// Width by dilation as an exact Euclidean distance search in two passes: first the nearest
// edge pixel of each class along the row (squared), then along the column.
const char* kDilateFragment = R"(#version 130
uniform sampler2D edges;
uniform ivec2 size;
uniform int radius;
out vec4 fragColor;
void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 best = vec3(1e6);
    float nearest = 1.0;
    for (int dx = -radius; dx <= radius; ++dx) {
        int x = p.x + dx;
        if (x < 0 || x >= size.x) continue;
        vec4 e = texelFetch(edges, ivec2(x, p.y), 0);
        best = min(best, mix(vec3(1e6), vec3(float(dx * dx)), e.rgb));
        if (e.r + e.g + e.b > 0.0) nearest = min(nearest, e.a);
    }
    fragColor = vec4(best, nearest);
}
)";

// Coverage: the marked band (both sides of an edge) is the line's two-pixel core, and a
// pixel d from the band's nearest centre lies about d + 0.5 from the edge itself, so a line
// of width w covers clamp(w/2 - d). The layers stack material, crease, silhouette (the most
// important on top), like cels. A pixel of the scene keeps its own depth; one over the
// background (outside the silhouette) takes the depth of the nearest edge that reaches it,
// so it covers the background but not what the program drew in front.
const char* kCompositeFragment = R"(#version 130
uniform sampler2D dilated;
uniform sampler2D depth;
uniform ivec2 size;
uniform ivec2 origin;
uniform int radius;
uniform vec3 widths;
uniform vec3 colours[3];
uniform float depthBias;
out vec4 fragColor;
void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy) - origin;
    vec3 best = vec3(1e6);
    float nearest = 1.0;
    for (int dy = -radius; dy <= radius; ++dy) {
        int y = p.y + dy;
        if (y < 0 || y >= size.y) continue;
        vec4 v = texelFetch(dilated, ivec2(p.x, y), 0);
        best = min(best, v.rgb + vec3(float(dy * dy)));
        nearest = min(nearest, v.a);
    }
    vec3 cover = clamp(0.5 * widths - sqrt(best), 0.0, 1.0);
    vec3 colour = colours[2] * cover.b;
    float alpha = cover.b;
    colour = colours[1] * cover.g + colour * (1.0 - cover.g);
    alpha = cover.g + alpha * (1.0 - cover.g);
    colour = colours[0] * cover.r + colour * (1.0 - cover.r);
    alpha = cover.r + alpha * (1.0 - cover.r);
    if (alpha <= 0.0) discard;
    float own = texelFetch(depth, p, 0).r;
    gl_FragDepth = max((own < 1.0 ? own : nearest) - depthBias, 0.0);
    fragColor = vec4(colour / alpha, alpha);
}
)";

std::unique_ptr<Style> create() { return std::make_unique<EdgesStyle>(); }

} // namespace

StyleInfo edgesStyleInfo()
{
    StyleInfo info;
    info.name = kStyle;
    info.summary = "image-space outlines: edges of depth, normal and id buffers, widened and "
                   "composited (thesis 4.1.2, 3.1.4)";
    info.role = StyleRole::Outline;
    info.create = &create;
    auto& p = info.params;
    p.push_back(ParamInfo::number("silhouette_width",
                                  "width in pixels of silhouettes (depth edges), 0: none", 2.0,
                                  0.0, 16.0));
    p.push_back(ParamInfo::number("crease_width",
                                  "width in pixels of creases (normal edges), 0: none", 2.0,
                                  0.0, 16.0));
    p.push_back(ParamInfo::number(
        "material_width",
        "width in pixels of material edges (other object or colour), 0: none", 2.0, 0.0, 16.0));
    p.push_back(ParamInfo::number(
        "depth_threshold",
        "relative jump of view depth between neighbouring pixels that makes a silhouette",
        0.05, 0.001, 1.0));
    p.push_back(ParamInfo::number(
        "crease_angle", "angle in degrees between neighbouring normals that makes a crease",
        50.0, 1.0, 179.0));
    p.push_back(ParamInfo::number(
        "colour_threshold",
        "change of a colour channel (0-1) between neighbouring pixels that makes a material "
        "edge",
        0.15, 0.01, 1.0));
    addInkParams(p);
    for (const char* c : {"silhouette", "crease", "material"}) addLightnessParam(p, c, 0.0);
    return info;
}

bool EdgesStyle::init(StyleContext& ctx, std::string& error)
{
    const GlFunctions& gl = ctx.gl;
    if (!mGeometry.build(gl, kGeometryVertex, kGeometryFragment, error) ||
        !mDetect.build(gl, kFullscreenVertex, kDetectFragment, error) ||
        !mDilate.build(gl, kFullscreenVertex, kDilateFragment, error) ||
        !mComposite.build(gl, kFullscreenVertex, kCompositeFragment, error)) {
        return false;
    }
    mGeo = {mGeometry.uniform(gl, "modelview"),    mGeometry.uniform(gl, "projection"),
            mGeometry.uniform(gl, "normalMatrix"), mGeometry.uniform(gl, "objectId"),
            mGeometry.uniform(gl, "orthographic"), mGeometry.uniform(gl, "depthRange")};
    mDet = {mDetect.uniform(gl, "attributes"),     mDetect.uniform(gl, "normals"),
            mDetect.uniform(gl, "depth"),          mDetect.uniform(gl, "size"),
            mDetect.uniform(gl, "depthThreshold"), mDetect.uniform(gl, "creaseCosine"),
            mDetect.uniform(gl, "colourThreshold")};
    mDil = {mDilate.uniform(gl, "edges"), mDilate.uniform(gl, "size"),
            mDilate.uniform(gl, "radius")};
    mCom = {mComposite.uniform(gl, "dilated"), mComposite.uniform(gl, "depth"),
            mComposite.uniform(gl, "size"),    mComposite.uniform(gl, "origin"),
            mComposite.uniform(gl, "radius"),  mComposite.uniform(gl, "widths"),
            mComposite.uniform(gl, "colours"), mComposite.uniform(gl, "depthBias")};

    mWidths = {float(ctx.param(kStyle, "silhouette_width")),
               float(ctx.param(kStyle, "crease_width")),
               float(ctx.param(kStyle, "material_width"))};
    mColours[0] = classColour(ctx, kStyle, "silhouette_lightness");
    mColours[1] = classColour(ctx, kStyle, "crease_lightness");
    mColours[2] = classColour(ctx, kStyle, "material_lightness");
    mDepthThreshold = float(ctx.param(kStyle, "depth_threshold"));
    mCreaseCosine = float(std::cos(glm::radians(ctx.param(kStyle, "crease_angle"))));
    mColourThreshold = float(ctx.param(kStyle, "colour_threshold"));
    // Far enough for the widest class (see the composite's coverage).
    const float widest = std::max({mWidths.x, mWidths.y, mWidths.z});
    mRadius = int(std::ceil(0.5f * widest));

    const float triangle[] = {-1.0f, -1.0f, 0.0f, 3.0f, -1.0f, 0.0f, -1.0f, 3.0f, 0.0f};
    gl.GenBuffers(1, &mTriangle);
    gl.BindBuffer(GL_ARRAY_BUFFER, mTriangle);
    gl.BufferData(GL_ARRAY_BUFFER, sizeof(triangle), triangle, GL_STATIC_DRAW);
    gl.BindBuffer(GL_ARRAY_BUFFER, 0);
    return true;
}

void EdgesStyle::drawFullscreen(const GlFunctions& gl)
{
    gl.BindBuffer(GL_ARRAY_BUFFER, mTriangle);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    gl.EnableVertexAttribArray(0);
    for (GLuint a = 1; a < 4; ++a) gl.DisableVertexAttribArray(a);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

void EdgesStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    const int width = scene.viewport.z, height = scene.viewport.w;
    if (scene.objects.empty() || width <= 0 || height <= 0) return;
    GLint drawFbo = 0, readFbo = 0;
    gl.GetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo);
    gl.GetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFbo);
    auto bindBack = [&] {
        gl.BindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFbo));
        gl.BindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFbo));
    };
    if (!mTargets.ensure(gl, width, height)) {
        bindBack();
        return;
    }

    // 1. The scene's attributes off screen. The polygon offset is stronger than the one a
    // shading style draws with, so the stored depth never loses against the program's.
    gl.BindFramebuffer(GL_FRAMEBUFFER, mTargets.geometryFbo());
    gl.Viewport(0, 0, width, height);
    gl.ClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    gl.ClearDepth(1.0);
    gl.DepthMask(GL_TRUE);
    gl.Clear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    gl.DepthFunc(GL_LESS);
    gl.PolygonOffset(-2.0f, -4.0f);
    gl.UseProgram(mGeometry.id());
    for (const SceneObject& o : scene.objects) {
        const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(o.modelview));
        gl.UniformMatrix4fv(mGeo.modelview, 1, GL_FALSE, glm::value_ptr(o.modelview));
        gl.UniformMatrix4fv(mGeo.projection, 1, GL_FALSE, glm::value_ptr(o.projection));
        gl.UniformMatrix3fv(mGeo.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
        gl.Uniform1f(mGeo.objectId, float(o.id));
        // A projection without a perspective row is orthographic; its P[2][2] is -2/range.
        const bool ortho = o.projection[0][3] == 0.0f && o.projection[1][3] == 0.0f &&
                           o.projection[2][3] == 0.0f;
        gl.Uniform1i(mGeo.orthographic, ortho ? 1 : 0);
        gl.Uniform1f(mGeo.depthRange, 2.0f / std::max(std::abs(o.projection[2][2]), 1e-12f));
        ctx.meshes.draw(gl, *o.mesh);
    }
    gl.Disable(GL_POLYGON_OFFSET_FILL);
    gl.Disable(GL_DEPTH_TEST);
    gl.DepthMask(GL_FALSE);

    // 2. Edge operator.
    gl.BindFramebuffer(GL_FRAMEBUFFER, mTargets.edgeFbo());
    gl.UseProgram(mDetect.id());
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, mTargets.attributes());
    gl.ActiveTexture(GL_TEXTURE1);
    gl.BindTexture(GL_TEXTURE_2D, mTargets.normals());
    gl.ActiveTexture(GL_TEXTURE2);
    gl.BindTexture(GL_TEXTURE_2D, mTargets.depth());
    gl.Uniform1i(mDet.attributes, 0);
    gl.Uniform1i(mDet.normals, 1);
    gl.Uniform1i(mDet.depth, 2);
    gl.Uniform2i(mDet.size, width, height);
    gl.Uniform1f(mDet.depthThreshold, mDepthThreshold);
    gl.Uniform1f(mDet.creaseCosine, mCreaseCosine);
    gl.Uniform1f(mDet.colourThreshold, mColourThreshold);
    drawFullscreen(gl);

    // 3. Rows of the distance search.
    gl.BindFramebuffer(GL_FRAMEBUFFER, mTargets.dilateFbo());
    gl.UseProgram(mDilate.id());
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, mTargets.edges());
    gl.Uniform1i(mDil.edges, 0);
    gl.Uniform2i(mDil.size, width, height);
    gl.Uniform1i(mDil.radius, mRadius);
    drawFullscreen(gl);

    // 4. Columns, coverage and the composite into the program's framebuffer.
    bindBack();
    gl.Viewport(scene.viewport.x, scene.viewport.y, width, height);
    GLint depthBits = 0;
    gl.GetIntegerv(GL_DEPTH_BITS, &depthBits);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LEQUAL);
    gl.Enable(GL_BLEND);
    gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    gl.UseProgram(mComposite.id());
    gl.ActiveTexture(GL_TEXTURE0);
    gl.BindTexture(GL_TEXTURE_2D, mTargets.dilated());
    gl.ActiveTexture(GL_TEXTURE1);
    gl.BindTexture(GL_TEXTURE_2D, mTargets.depth());
    gl.Uniform1i(mCom.dilated, 0);
    gl.Uniform1i(mCom.depth, 1);
    gl.Uniform2i(mCom.size, width, height);
    gl.Uniform2i(mCom.origin, scene.viewport.x, scene.viewport.y);
    gl.Uniform1i(mCom.radius, mRadius);
    gl.Uniform3fv(mCom.widths, 1, glm::value_ptr(mWidths));
    gl.Uniform3fv(mCom.colours, 3, glm::value_ptr(mColours[0]));
    // Two steps of the program's depth format: its rounding must not hide the ink.
    const int bits = std::clamp(int(depthBits), 8, 24);
    gl.Uniform1f(mCom.depthBias, 2.0f / float(1 << bits));
    drawFullscreen(gl);

    for (GLenum unit : {GL_TEXTURE2, GL_TEXTURE1, GL_TEXTURE0}) {
        gl.ActiveTexture(unit);
        gl.BindTexture(GL_TEXTURE_2D, 0);
    }
}

void EdgesStyle::shutdown(StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    mTargets.destroy(gl);
    if (mTriangle) gl.DeleteBuffers(1, &mTriangle);
    mTriangle = 0;
    for (ShaderProgram* p : {&mGeometry, &mDetect, &mDilate, &mComposite}) p->destroy(gl);
}

} // namespace nprgl::styles
