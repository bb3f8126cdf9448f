#include "styles/outlines/WireframeStyle.h"

#include "styles/FaceCulling.h"
#include "styles/StyleRegistry.h"
#include "styles/outlines/OutlineParams.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace nprgl::styles {

namespace {

constexpr const char* kStyle = "wireframe";

// Lines (and the stencil pass's faces) move towards the eye in depth only, so a line beats
// the surface it lies on without a z-fight; the screen position stays. The move is a fraction
// of the distance plus, for feature edges, the depth the steeper of the edge's two faces
// gains over the line's half width and one more pixel: the surface was drawn with a polygon
// offset that grows with its slope, and a wide line has one depth across its width.
const char* kVertex = R"(#version 130
uniform mat4 modelview;
uniform mat4 projection;
uniform mat3 normalMatrix;
uniform float pull;
uniform bool featureEdge;
uniform float lineWidth;
uniform float pixelSize; // eye units per pixel at distance 1 (persp.) or anywhere (ortho)
uniform bool orthographic;
uniform float depthRange; // orthographic: far - near
in vec3 position;
in vec3 normal; // feature edges: the first face's normal
in vec4 color;  // feature edges: the second face's normal in xyz
out float viewDepth;
void main()
{
    vec4 eye = modelview * vec4(position, 1.0);
    eye.xyz /= eye.w;
    float distance = max(-eye.z, 1e-6);
    float move = pull * (orthographic ? depthRange : distance);
    if (featureEdge) {
        vec3 toEye = orthographic ? vec3(0.0, 0.0, 1.0) : normalize(-eye.xyz);
        float slope = 0.0;
        for (int k = 0; k < 2; ++k) {
            vec3 n = normalMatrix * (k == 0 ? normal : color.xyz);
            float c = max(abs(dot(normalize(n), toEye)), 0.05);
            slope = max(slope, sqrt(1.0 - c * c) / c);
        }
        float footprint = pixelSize * (orthographic ? 1.0 : distance);
        move += footprint * (1.0 + 0.5 * lineWidth) * min(slope, 20.0);
    }
    vec4 clip = projection * vec4(eye.xyz, 1.0);
    vec3 moved = orthographic ? eye.xyz + vec3(0.0, 0.0, move)
                              : eye.xyz * (1.0 - move / distance);
    vec4 nearer = projection * vec4(moved, 1.0);
    clip.z = nearer.z / nearer.w * clip.w;
    gl_Position = clip;
    viewDepth = distance;
}
)";

const char* kFragment = R"(#version 130
uniform vec3 inkColor;
uniform vec3 fadeColor;
uniform vec2 cueRange;
uniform float depthCue;
uniform bool roundPoints;
uniform bool smoothEdges;
uniform float pointSize;
in float viewDepth;
out vec4 fragColor;
void main()
{
    float alpha = 1.0;
    if (roundPoints) {
        // Distance from the point's centre in pixels; outside the disc is not ink.
        float r = length(gl_PointCoord - vec2(0.5)) * pointSize;
        float edge = 0.5 * pointSize - r;
        if (edge < (smoothEdges ? -0.5 : 0.0)) discard;
        if (smoothEdges) alpha = clamp(edge + 0.5, 0.0, 1.0);
    }
    float t = clamp((viewDepth - cueRange.x) / max(cueRange.y - cueRange.x, 1e-6), 0.0, 1.0);
    fragColor = vec4(mix(inkColor, fadeColor, depthCue * t), alpha);
}
)";

std::unique_ptr<Style> create() { return std::make_unique<WireframeStyle>(); }

const char* const kClassNames[] = {"silhouette", "border", "crease", "material"};

} // namespace

StyleInfo wireframeStyleInfo()
{
    StyleInfo info;
    info.name = kStyle;
    info.summary = "wireframe outlines: back faces as wide lines behind the scene's depth, "
                   "creases and borders as lines (thesis 4.2)";
    info.role = StyleRole::Outline;
    info.create = &create;
    auto& p = info.params;
    p.push_back(ParamInfo::number(
        "silhouette_width",
        "width in pixels of the back-face lines; about half of it shows outside the object",
        4.0, 1.0, 32.0));
    p.push_back(ParamInfo::number("crease_width", "width in pixels of crease lines", 2.0, 1.0,
                                  32.0));
    p.push_back(ParamInfo::number("border_width",
                                  "width in pixels of border lines (edges with one face)", 2.0,
                                  1.0, 32.0));
    p.push_back(ParamInfo::number("material_width",
                                  "width in pixels of lines between different materials", 2.0,
                                  1.0, 32.0));
    p.push_back(ParamInfo::flag("creases", "draw creases (dihedral angle above the threshold)",
                                true));
    p.push_back(ParamInfo::flag("borders", "draw border edges of open surfaces", true));
    p.push_back(ParamInfo::flag("material_edges", "draw edges between different materials",
                                true));
    addInkParams(p);
    for (const char* c : kClassNames) addLightnessParam(p, c, 0.0);
    p.push_back(ParamInfo::flag("antialias", "smooth lines and points blended over the picture",
                                false));
    p.push_back(ParamInfo::flag(
        "vertex_points", "round points at the vertices fill the gaps between wide segments",
        true));
    p.push_back(ParamInfo::flag(
        "stencil",
        "keep silhouette lines off each object's own visible surface (overwrites the stencil "
        "buffer; needs one)",
        false));
    p.push_back(ParamInfo::number(
        "depth_cue", "how far distant lines fade towards the clear colour (HijackGL), 0: off",
        0.0, 0.0, 1.0));
    p.push_back(ParamInfo::number(
        "depth_bias",
        "creases, borders and material lines move this fraction of their distance (and by "
        "their faces' slope) towards the eye to win over their surface; silhouettes are "
        "lifted by a polygon offset",
        0.002, 0.0, 0.05));
    return info;
}

bool WireframeStyle::init(StyleContext& ctx, std::string& error)
{
    const GlFunctions& gl = ctx.gl;
    if (!mProgram.build(gl, kVertex, kFragment, error)) return false;
    mLoc.modelview = mProgram.uniform(gl, "modelview");
    mLoc.projection = mProgram.uniform(gl, "projection");
    mLoc.pull = mProgram.uniform(gl, "pull");
    mLoc.inkColor = mProgram.uniform(gl, "inkColor");
    mLoc.fadeColor = mProgram.uniform(gl, "fadeColor");
    mLoc.cueRange = mProgram.uniform(gl, "cueRange");
    mLoc.depthCue = mProgram.uniform(gl, "depthCue");
    mLoc.roundPoints = mProgram.uniform(gl, "roundPoints");
    mLoc.smoothEdges = mProgram.uniform(gl, "smoothEdges");
    mLoc.pointSize = mProgram.uniform(gl, "pointSize");
    mLoc.normalMatrix = mProgram.uniform(gl, "normalMatrix");
    mLoc.featureEdge = mProgram.uniform(gl, "featureEdge");
    mLoc.lineWidth = mProgram.uniform(gl, "lineWidth");
    mLoc.pixelSize = mProgram.uniform(gl, "pixelSize");
    mLoc.orthographic = mProgram.uniform(gl, "orthographic");
    mLoc.depthRange = mProgram.uniform(gl, "depthRange");

    // The settings are fixed for the chain's life: read them once.
    const char* widths[] = {"silhouette_width", "border_width", "crease_width",
                            "material_width"};
    const char* flags[] = {nullptr, "borders", "creases", "material_edges"};
    for (int c = 0; c < ClassCount; ++c) {
        LineClass& lc = mClasses[c];
        lc.enabled = !flags[c] || ctx.param(kStyle, flags[c]) != 0.0;
        lc.width = float(ctx.param(kStyle, widths[c]));
        const std::string lightness = std::string(kClassNames[c]) + "_lightness";
        lc.ink = inkClass(ctx, kStyle, lightness.c_str());
    }
    mAntialias = ctx.param(kStyle, "antialias") != 0.0;
    mPoints = ctx.param(kStyle, "vertex_points") != 0.0;
    mStencil = ctx.param(kStyle, "stencil") != 0.0;
    mDepthCue = float(ctx.param(kStyle, "depth_cue"));
    mPull = float(ctx.param(kStyle, "depth_bias"));

    gl.GetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, glm::value_ptr(mLineRange));
    gl.GetFloatv(GL_SMOOTH_LINE_WIDTH_RANGE, glm::value_ptr(mSmoothLineRange));
    gl.GetFloatv(GL_POINT_SIZE_RANGE, glm::value_ptr(mPointRange));
    return true;
}

void WireframeStyle::setClass(const StyleContext& ctx, const LineClass& c)
{
    const GlFunctions& gl = ctx.gl;
    const glm::vec2 range = mAntialias ? mSmoothLineRange : mLineRange;
    gl.LineWidth(std::clamp(c.width, range.x, std::max(range.x, range.y)));
    gl.PointSize(std::clamp(c.width, mPointRange.x, std::max(mPointRange.x, mPointRange.y)));
    gl.Uniform1f(mLoc.pointSize, c.width);
    gl.Uniform1f(mLoc.lineWidth, c.width);
    const glm::vec3 colour = c.ink.on(ctx.page);
    gl.Uniform3fv(mLoc.inkColor, 1, glm::value_ptr(colour));
}

void WireframeStyle::depthCueRange(const Scene& scene, StyleContext& ctx)
{
    float lo = std::numeric_limits<float>::max(), hi = -lo;
    for (const SceneObject& o : scene.objects) {
        const EdgeLines::Lines& lines = mEdges.bind(ctx.gl, *o.mesh);
        for (int k = 0; k < 8; ++k) {
            glm::vec3 p((k & 1) ? lines.boundsMax.x : lines.boundsMin.x,
                        (k & 2) ? lines.boundsMax.y : lines.boundsMin.y,
                        (k & 4) ? lines.boundsMax.z : lines.boundsMin.z);
            const float depth = -(o.modelview * glm::vec4(p, 1.0f)).z;
            lo = std::min(lo, depth);
            hi = std::max(hi, depth);
        }
    }
    ctx.gl.Uniform2f(mLoc.cueRange, lo, std::max(hi, lo));
}

void WireframeStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    if (scene.objects.empty() || scene.viewport.z <= 0 || scene.viewport.w <= 0) return;
    gl.UseProgram(mProgram.id());
    gl.Uniform1f(mLoc.pull, mPull);
    gl.Uniform1f(mLoc.depthCue, mDepthCue);
    gl.Uniform3f(mLoc.fadeColor, scene.clearColor.r, scene.clearColor.g, scene.clearColor.b);
    gl.Uniform1i(mLoc.roundPoints, 0);
    gl.Uniform1i(mLoc.featureEdge, 0);
    gl.Uniform1i(mLoc.smoothEdges, mAntialias ? 1 : 0);
    if (mDepthCue > 0.0f) depthCueRange(scene, ctx);
    else gl.Uniform2f(mLoc.cueRange, 0.0f, 1.0f);

    // Lines only test against the scene's depth: they never hide each other or later passes.
    gl.DepthMask(GL_FALSE);
    gl.Disable(GL_POLYGON_OFFSET_FILL); // the shader's pull replaces it
    if (mAntialias) {
        gl.Enable(GL_LINE_SMOOTH);
        gl.Hint(GL_LINE_SMOOTH_HINT, GL_NICEST);
        gl.Enable(GL_BLEND);
        // Keep the program's destination alpha.
        gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    }

    // Stencil: each object's visible front faces take its id; its silhouette lines are then
    // drawn only where the id differs, so they stay off its shaded interior (where depth
    // imprecision would let single pixels through) but still cross other objects and the
    // background. Ids wrap after 255 objects.
    GLint stencilBits = 0;
    if (mStencil) gl.GetIntegerv(GL_STENCIL_BITS, &stencilBits);
    const bool useStencil = stencilBits > 0;
    if (useStencil) {
        ctx.scissorTo(scene, scene.viewport);
        gl.StencilMask(0xff);
        gl.ClearStencil(0);
        gl.Clear(GL_STENCIL_BUFFER_BIT);
        ctx.endScissor(scene);
        gl.ColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
        gl.Enable(GL_CULL_FACE);
        gl.CullFace(GL_BACK);
        gl.Enable(GL_STENCIL_TEST);
        gl.StencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            const SceneObject& o = scene.objects[i];
            if (o.culled == GL_FRONT_AND_BACK) continue;
            gl.FrontFace(FaceCulling::shownWinding(o));
            gl.StencilFunc(GL_ALWAYS, GLint(i % 255 + 1), 0xff);
            gl.UniformMatrix4fv(mLoc.modelview, 1, GL_FALSE, glm::value_ptr(o.modelview));
            gl.UniformMatrix4fv(mLoc.projection, 1, GL_FALSE, glm::value_ptr(o.projection));
            ctx.meshes.draw(gl, *o.mesh);
        }
        gl.StencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
        gl.Disable(GL_STENCIL_TEST);
        gl.FrontFace(GL_CCW);
        ctx.colourMaskOn();
    }

    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        if (o.culled == GL_FRONT_AND_BACK) continue; // the program shows none of it
        gl.UniformMatrix4fv(mLoc.modelview, 1, GL_FALSE, glm::value_ptr(o.modelview));
        gl.UniformMatrix4fv(mLoc.projection, 1, GL_FALSE, glm::value_ptr(o.projection));
        const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(o.modelview));
        gl.UniformMatrix3fv(mLoc.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
        const bool ortho = o.orthographic();
        gl.Uniform1i(mLoc.orthographic, ortho ? 1 : 0);
        gl.Uniform1f(mLoc.depthRange, 2.0f / std::max(std::abs(o.projection[2][2]), 1e-12f));
        // The projection maps 2 / P[1][1] eye units (at distance 1) onto the viewport height.
        gl.Uniform1f(mLoc.pixelSize, 2.0f / (std::abs(o.projection[1][1]) *
                                             float(scene.viewport.w)));
        drawSilhouette(o, ctx, useStencil ? uint8_t(i % 255 + 1) : 0);
        drawFeatureEdges(o, ctx);
    }
    mEdges.endFlush(gl);
}

void WireframeStyle::drawSilhouette(const SceneObject& object, StyleContext& ctx,
                                    uint8_t stencilId)
{
    const GlFunctions& gl = ctx.gl;
    if (stencilId) {
        gl.Enable(GL_STENCIL_TEST);
        gl.StencilFunc(GL_NOTEQUAL, stencilId, 0xff);
    }
    // Back faces only (the side the program turns away or culls): their edges behind the
    // object fail the depth test, the ones on the rim stick out as a halo.
    gl.Enable(GL_CULL_FACE);
    gl.FrontFace(FaceCulling::shownWinding(object));
    gl.CullFace(GL_FRONT);
    // Not pulled by a share of the distance, as lines on a face are: a thin part (a shell, a
    // coin) would then show its back faces' edges all over its front. A polygon offset pulls
    // them by their slope: the rim's grazing faces win against the front faces there, the
    // back faces behind a surface stay behind it.
    gl.Uniform1f(mLoc.pull, 0.0f);
    gl.Enable(GL_POLYGON_OFFSET_LINE);
    gl.Enable(GL_POLYGON_OFFSET_POINT);
    gl.PolygonOffset(-1.0f, -2.0f);
    setClass(ctx, mClasses[Silhouette]);
    gl.PolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    ctx.meshes.draw(gl, *object.mesh);
    if (mPoints && mClasses[Silhouette].width > 2.0f) {
        gl.PolygonMode(GL_FRONT_AND_BACK, GL_POINT);
        gl.Enable(GL_POINT_SPRITE);
        gl.Uniform1i(mLoc.roundPoints, 1);
        ctx.meshes.draw(gl, *object.mesh);
        gl.Uniform1i(mLoc.roundPoints, 0);
        gl.Disable(GL_POINT_SPRITE);
    }
    gl.PolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    gl.Disable(GL_POLYGON_OFFSET_LINE);
    gl.Disable(GL_POLYGON_OFFSET_POINT);
    gl.Uniform1f(mLoc.pull, mPull);
    gl.Disable(GL_CULL_FACE);
    gl.FrontFace(GL_CCW);
    if (stencilId) gl.Disable(GL_STENCIL_TEST);
}

void WireframeStyle::drawFeatureEdges(const SceneObject& object, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    const EdgeLines::Lines& lines = mEdges.bind(gl, *object.mesh);
    const GLsizei stride = sizeof(EdgeLines::Vertex);
    auto at = [](size_t offset) { return reinterpret_cast<const void*>(offset); };
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                           at(offsetof(EdgeLines::Vertex, position)));
    gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                           at(offsetof(EdgeLines::Vertex, faceNormal0)));
    gl.VertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride,
                           at(offsetof(EdgeLines::Vertex, faceNormal1)));
    for (GLuint a = 0; a < 3; ++a) gl.EnableVertexAttribArray(a);
    gl.DisableVertexAttribArray(3);
    gl.Uniform1i(mLoc.featureEdge, 1);
    for (int k = 0; k < EdgeLines::KindCount; ++k) {
        const LineClass& c = mClasses[k + 1];
        if (!c.enabled || lines.count[size_t(k)] == 0) continue;
        setClass(ctx, c);
        gl.DrawArrays(GL_LINES, lines.first[size_t(k)], lines.count[size_t(k)]);
        if (mPoints && c.width > 2.0f) {
            gl.Enable(GL_POINT_SPRITE);
            gl.Uniform1i(mLoc.roundPoints, 1);
            gl.DrawArrays(GL_POINTS, lines.first[size_t(k)], lines.count[size_t(k)]);
            gl.Uniform1i(mLoc.roundPoints, 0);
            gl.Disable(GL_POINT_SPRITE);
        }
    }
    gl.Uniform1i(mLoc.featureEdge, 0);
}

void WireframeStyle::shutdown(StyleContext& ctx)
{
    mEdges.destroy(ctx.gl);
    mProgram.destroy(ctx.gl);
}

} // namespace nprgl::styles
