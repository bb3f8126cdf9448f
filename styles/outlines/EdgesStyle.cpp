#include "styles/outlines/EdgesStyle.h"

#include "common/Log.h"
#include "styles/FaceCulling.h"
#include "styles/ObjectNames.h"
#include "styles/StyleRegistry.h"
#include "styles/outlines/FeatureLines.h"
#include "styles/outlines/OutlineParams.h"
#include "styles/shading/ShadingCommon.h"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace nprgl::styles {

namespace {

constexpr const char* kStyle = "edges";

// CUT 1: the variant for cut-outs, which carries their texture coordinates (kCutTest).
const char* kGeometryVertex = R"(
uniform mat4 modelview;
uniform mat4 projection;
uniform mat3 normalMatrix;
in vec3 position;
in vec3 normal;
in vec4 color;
out vec3 eyeNormal;
out float viewDepth;
out vec4 baseColor;
#if CUT
in vec2 texcoord;
out vec2 uv;
#endif
void main()
{
    vec4 eye = modelview * vec4(position, 1.0);
    eyeNormal = normalMatrix * normal;
    viewDepth = -eye.z / eye.w;
    baseColor = color;
#if CUT
    uv = texcoord;
#endif
    gl_Position = projection * eye;
}
)";

// A cut-out's attributes only where the program's alpha test keeps its fragment (its
// texture's alpha times its colour's), so the operator finds its lines along the cut. A
// variant of its own: the others would pay for the texture read (llvmpipe runs it anyway).
const char* kCutTest = R"(
#if CUT
uniform sampler2D cutTexture;
uniform bool cutTextured;
uniform int alphaFunc; // the program's, less GL_NEVER: 0 never ... 7 always
uniform float alphaRef;
in vec2 uv;
bool kept(float a)
{
    return alphaFunc == 1 ? a < alphaRef
           : alphaFunc == 2 ? a == alphaRef
           : alphaFunc == 3 ? a <= alphaRef
           : alphaFunc == 4 ? a > alphaRef
           : alphaFunc == 5 ? a != alphaRef
           : alphaFunc == 6 ? a >= alphaRef
                            : alphaFunc == 7;
}
#endif
void cutTest(vec4 colour)
{
#if CUT
    float a = colour.a * (cutTextured ? texture(cutTexture, uv).a : 1.0);
    if (!kept(a)) discard;
#endif
}
)";

// One RGBA32UI target, so the edge operator fetches each pixel once:
//   x: log2 of the view depth in 8.24 fixed point (relative depth jumps become differences),
//      0 for the background;
//   y: window depth (24 bits; the background is cleared to 1) | id bits 0-7 << 24;
//   z: colour, 8 bits a channel | id bits 8-15 << 24;
//   w: the unit eye normal facing the viewer, 10 bits a component; bit 31: the object is
//      small on screen and gets no material lines (its colours show the change; lines
//      between them made a small ship a blot of ink); bit 30: smaller still, its lines are
//      one pixel wide (see the operator).
// An orthographic view may put the eye anywhere, so there the depth is measured from one
// depth range in front of the near plane (relative jumps are then relative to the range).
const char* kGeometryFragment = R"(
uniform float objectId;
uniform bool orthographic;
uniform float depthRange;
uniform bool noMaterial; // small on screen: no material lines (w bit 31)
uniform bool thinLines;  // smaller still: lines of one pixel (w bit 30)
in vec3 eyeNormal;
in float viewDepth;
in vec4 baseColor;
out uvec4 fragColor;
void main()
{
    cutTest(baseColor);
    vec3 n = normalize(eyeNormal);
    if (!gl_FrontFacing) n = -n;
#if CUT
    // Facing the eye: a cut-out's lines are its cut's (silhouettes and other objects), not
    // creases where the quads it is drawn on cross (a tree of two crossed billboards).
    n = vec3(0.0, 0.0, 1.0);
#endif
    float z = orthographic ? (1.0 + gl_FragCoord.z) * depthRange : max(viewDepth, 1e-6);
    uint logDepth = uint(clamp((log2(z) + 64.0) * 16777216.0, 1.0, 2147483520.0));
    uint window = uint(clamp(gl_FragCoord.z, 0.0, 1.0) * 16777215.0 + 0.5);
    uvec3 c = uvec3(clamp(baseColor.rgb, 0.0, 1.0) * 255.0 + 0.5);
    uvec3 q = uvec3(clamp(n * 0.5 + 0.5, 0.0, 1.0) * 1023.0 + 0.5);
    uint id = uint(objectId) & 0xffffu;
    fragColor = uvec4(logDepth, window | (id << 24),
                      (c.r << 16) | (c.g << 8) | c.b | ((id >> 8) << 24),
                      q.x | (q.y << 10) | (q.z << 20) | (noMaterial ? 0x80000000u : 0u) |
                          (thinLines ? 0x40000000u : 0u));
}
)";

// The direct pass, drawn over the feature lines of each object, or (identity matrices) over
// the one triangle covering the viewport.
const char* kPlacedVertex = R"(#version 130
uniform mat4 modelview;
uniform mat4 projection;
in vec3 position;
void main() { gl_Position = projection * (modelview * vec4(position, 1.0)); }
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
// colour at continuous depth. Neighbours are clamped into the scissored rectangle (outside
// it the target holds stale pixels); a pixel compared with itself finds nothing, and the
// rectangle's rim is background, so that equals skipping them.
const char* kOperator = R"(#version 130
uniform usampler2D attributes;
uniform ivec4 rect;          // lowest and highest pixel of the scissored rectangle
uniform float depthStep;     // log2(1 + threshold) in the depth's fixed point
uniform float creaseCosine;
uniform float colourThreshold; // in 1/255 steps
uniform bool objectSeams;
out vec4 fragColor;

float windowDepth(uint y) { return float(y & 0xffffffu) * (1.0 / 16777215.0); }
vec3 unpackColour(uint z) { return vec3(uvec3(z >> 16, z >> 8, z) & 255u); }
// Quantised from a unit vector, so within 0.2% of unit length: no normalize needed.
vec3 unpackNormal(uint w)
{
    return vec3(uvec3(w, w >> 10, w >> 20) & 1023u) * (2.0 / 1023.0) - 1.0;
}

// The line classes between pixel c and its neighbour s: r silhouette, g crease, b material.
vec3 classify(uvec4 c, uvec4 s)
{
    if (c.x == 0u && s.x == 0u) return vec3(0.0);
    if (c.x == 0u || s.x == 0u || float(max(s.x, c.x) - min(s.x, c.x)) > depthStep) {
        return vec3(1.0, 0.0, 0.0);
    }
    // Another object continuing the same surface in the same colour (a tube drawn in
    // segments, a floor in tiles) is no edge unless seams are asked for; where it turns or
    // changes colour it is a material edge.
    bool otherObject = (((s.y ^ c.y) | (s.z ^ c.z)) >> 24) != 0u;
    bool otherColour = ((c.w | s.w) & 0x80000000u) == 0u &&
        any(greaterThan(abs(unpackColour(s.z) - unpackColour(c.z)), vec3(colourThreshold)));
    bool turns = dot(unpackNormal(c.w), unpackNormal(s.w)) < creaseCosine;
    bool plain = ((c.w | s.w) & 0x80000000u) != 0u;
    if (otherColour || (otherObject && !plain && (objectSeams || turns))) {
        return vec3(0.0, 0.0, 1.0);
    }
    return turns ? vec3(0.0, 1.0, 0.0) : vec3(0.0);
}

bool differs(uvec4 a, uvec4 b) { return classify(a, b) != vec3(0.0); }

uvec4 at(ivec2 q) { return texelFetch(attributes, clamp(q, rect.xy, rect.zw), 0); }

// Line classes starting at p (r silhouette, g crease, b material); a the window depth of the
// nearest side; own: p's window depth (1 for the background). A speck, one pixel unlike its
// four neighbours (a sliver of a surface poking through another, a part smaller than a
// pixel), draws no line: its outline would be a cross of ink bigger than the thing itself.
// Whether a and b belong to different objects (the background is object 0): the speck test
// below. Not by depth: at a grazing silhouette one surface's neighbouring pixels jump in depth.
bool apart(uvec4 a, uvec4 b) { return (((a.y ^ b.y) | (a.z ^ b.z)) >> 24) != 0u; }
bool thin(uvec4 a) { return (a.w & 0x40000000u) != 0u; }
// Whether the line between thin-lined object c and its neighbour s is drawn on s: s is of
// another object, and not a thin-lined one in front of c (between two such objects the
// farther takes it).
bool outside(uvec4 c, uvec4 s)
{
    return apart(c, s) && (!thin(s) || windowDepth(s.y) >= windowDepth(c.y));
}

vec4 detect(ivec2 p, out float own)
{
    uvec4 c = at(p);
    uvec4 e = at(p + ivec2(1, 0)), w = at(p - ivec2(1, 0));
    uvec4 n = at(p + ivec2(0, 1)), s = at(p - ivec2(0, 1));
    vec3 ce = classify(c, e), cw = classify(c, w), cn = classify(c, n), cs = classify(c, s);
    own = windowDepth(c.y);
    // A speck (p, or the neighbour a line would be drawn against) is of another object than
    // all four of its neighbours.
    if (apart(c, e) && apart(c, w) && apart(c, n) && apart(c, s)) return vec4(vec3(0.0), own);
    uvec4 ne = at(p + ivec2(1, 1)), nw = at(p + ivec2(-1, 1));
    uvec4 se = at(p + ivec2(1, -1)), sw = at(p + ivec2(-1, -1));
    uvec4 e2 = at(p + ivec2(2, 0)), w2 = at(p - ivec2(2, 0));
    uvec4 n2 = at(p + ivec2(0, 2)), s2 = at(p - ivec2(0, 2));
    if (apart(e, c) && apart(e, e2) && apart(e, ne) && apart(e, se)) ce = vec3(0.0);
    if (apart(w, c) && apart(w, w2) && apart(w, nw) && apart(w, sw)) cw = vec3(0.0);
    if (apart(n, c) && apart(n, n2) && apart(n, ne) && apart(n, nw)) cn = vec3(0.0);
    if (apart(s, c) && apart(s, s2) && apart(s, se) && apart(s, sw)) cs = vec3(0.0);
    // Thin across (one or two pixels between other things: a wire, a beam, a rail far off):
    // no line on its own pixels along that axis, only on its neighbours' (which draw theirs
    // against it), so it keeps its colour between two lines instead of vanishing under them.
    bool toE = apart(c, e), toW = apart(c, w), toN = apart(c, n), toS = apart(c, s);
    if ((toE && toW) || (toW && apart(c, e2)) || (toE && apart(c, w2))) ce = cw = vec3(0.0);
    if ((toN && toS) || (toS && apart(c, n2)) || (toN && apart(c, s2))) cn = cs = vec3(0.0);
    // A tiny object (w bit 30) gets lines of one pixel: its outline on the pixels around it
    // (those of what lies behind it, or of the background), not on its own, and its creases
    // on one side. Drawn on both sides, lines of two pixels leave a thing a few pixels
    // across (a coin seen edge-on) a blot of ink.
    if (thin(c)) {
        if (outside(c, e)) ce = vec3(0.0);
        if (outside(c, w) || !toW) cw = vec3(0.0);
        if (outside(c, n)) cn = vec3(0.0);
        if (outside(c, s) || !toS) cs = vec3(0.0);
    }
    float nearest = own;
    if (ce.r > 0.0) nearest = min(nearest, windowDepth(e.y));
    if (cw.r > 0.0) nearest = min(nearest, windowDepth(w.y));
    if (cn.r > 0.0) nearest = min(nearest, windowDepth(n.y));
    if (cs.r > 0.0) nearest = min(nearest, windowDepth(s.y));
    return vec4(max(max(ce, cw), max(cn, cs)), nearest);
}
)";

const char* kDetectMain = R"(
void main()
{
    float own;
    vec4 e = detect(ivec2(gl_FragCoord.xy), own);
    fragColor = vec4(e.rgb, e.r + e.g + e.b > 0.0 ? e.a : 1.0);
}
)";

// The program's fog over the ink, as GL fogs what it draws: a line on a surface far into the
// fog fades into it with the surface (a horizon the fog hides keeps no line). The line's
// window depth back to the eye distance by the fogged objects' projection (P[2][2], P[3][2]).
// A variant without it (INK_FOG 0) for flushes without fog: llvmpipe runs both sides of a
// branch, and a full-window pass pays for every instruction.
const char* kInkFog = R"(
#if INK_FOG
uniform float fogMode;  // ShadingCommon::fogModeCode()
uniform vec3 fogRange;  // start, end, density
uniform vec3 fogColour;
uniform vec3 fogDepth;  // P[2][2], P[3][2], 1 for an orthographic projection
uniform vec2 windowRange; // glDepthRange
vec3 inkFog(vec3 ink, float windowDepth)
{
    float ndc = 2.0 * (windowDepth - windowRange.x) / max(windowRange.y - windowRange.x, 1e-6)
                - 1.0;
    float z = fogDepth.z > 0.5 ? (ndc - fogDepth.y) / fogDepth.x
                               : fogDepth.y / (fogDepth.x + ndc);
    return mix(fogColour, ink, fogFactor(fogMode, abs(z), fogRange));
}
#else
vec3 inkFog(vec3 ink, float windowDepth) { return ink; }
#endif
)";

// Lines of up to two pixels: a pixel d >= 1 from the marked band gets clamp(w/2 - d) = 0
// (see kCompositeFragment), so the coverage is min(w/2, 1) on the band and none elsewhere,
// and the operator feeds the composite directly.
const char* kDirectMain = R"(
uniform ivec2 origin;
uniform vec3 cover;
uniform vec3 colours[3];
uniform float depthBias;
void main()
{
    float own;
    vec4 e = detect(ivec2(gl_FragCoord.xy) - origin, own);
    if (e.r + e.g + e.b == 0.0) discard;
    vec3 c = e.rgb * cover;
    vec3 colour = colours[2] * c.b;
    float alpha = c.b;
    colour = colours[1] * c.g + colour * (1.0 - c.g);
    alpha = c.g + alpha * (1.0 - c.g);
    colour = colours[0] * c.r + colour * (1.0 - c.r);
    alpha = c.r + alpha * (1.0 - c.r);
    if (alpha <= 0.0) discard;
    float depth = own < 1.0 ? own : e.a;
    gl_FragDepth = max(depth - depthBias, 0.0);
    fragColor = vec4(inkFog(colour / alpha, depth), alpha);
}
)";

// Width by dilation as an exact Euclidean distance search in two passes: first the nearest
// edge pixel of each class along the row (squared), then along the column. A neighbour
// clamped into the rectangle was also visited at its true distance, so the minimum holds.
const char* kDilateFragment = R"(#version 130
uniform sampler2D edges;
uniform ivec4 rect;
uniform int radius;
out vec4 fragColor;
void main()
{
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec3 best = vec3(1e6);
    float nearest = 1.0;
    for (int dx = -radius; dx <= radius; ++dx) {
        vec4 e = texelFetch(edges, ivec2(clamp(p.x + dx, rect.x, rect.z), p.y), 0);
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
const char* kCompositeFragment = R"(
uniform sampler2D dilated;
uniform usampler2D attributes;
uniform ivec4 rect;
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
        vec4 v = texelFetch(dilated, ivec2(p.x, clamp(p.y + dy, rect.y, rect.w)), 0);
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
    float own = float(texelFetch(attributes, p, 0).y & 0xffffffu) * (1.0 / 16777215.0);
    float depth = own < 1.0 ? own : nearest;
    gl_FragDepth = max(depth - depthBias, 0.0);
    fragColor = vec4(inkFog(colour / alpha, depth), alpha);
}
)";

// The band the direct pass runs on around each feature line: the operator marks the pixel on
// each side of an edge, both within 1.5 pixels of it; points as wide cover the lines' ends.
constexpr float kNearWidth = 3.0f;
constexpr double kLineSetup = 48.0; // fragments (see planNear)
// Pixels: a cut-out whose kept parts or enclosed holes are finer on screen gets no lines
// along its cut (footprint()).
constexpr float kFineCut = 3.0f;

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
    p.push_back(ParamInfo::flag(
        "object_seams",
        "lines where one object meets another on a smooth surface of the same colour (the "
        "seams of geometry drawn in pieces: tube segments, floor tiles)",
        false));
    p.push_back(ParamInfo::number(
        "detail_size",
        "objects smaller than this on screen (pixels, their larger side) get no material "
        "lines (their colours show the change); 0: none",
        64.0, 0.0, 4096.0));
    p.push_back(ParamInfo::number(
        "thin_size",
        "objects smaller than this on screen (pixels, their larger side) get lines of one "
        "pixel, their outline drawn around them, not over them; 0: none",
        32.0, 0.0, 4096.0));
    p.push_back(ParamInfo::choice(
        "pass",
        "where the edge operator runs for lines of up to 2 pixels: auto (on the pixels near the "
        "objects' feature edges when those are fewer than the scene's rectangle), full (the "
        "whole rectangle: also finds where surfaces cut through each other) or lines (always "
        "near the feature edges)",
        {"auto", "full", "lines"}, 0));
    addInkParams(p);
    for (const char* c : {"silhouette", "crease", "material"}) addLightnessParam(p, c, 0.0);
    return info;
}

bool EdgesStyle::init(StyleContext& ctx, std::string& error)
{
    const GlFunctions& gl = ctx.gl;
    const std::string detect = std::string(kOperator) + kDetectMain;
    std::string direct[2], composite[2];
    for (int fogged = 0; fogged < 2; ++fogged) {
        const std::string fog = std::string("#define INK_FOG ") + (fogged ? "1\n" : "0\n") +
                                ShadingCommon::fogFactorFunction() + kInkFog;
        direct[fogged] = std::string(kOperator) + fog + kDirectMain;
        composite[fogged] = "#version 130\n" + fog + kCompositeFragment;
    }
    for (int cut = 0; cut < 2; ++cut) {
        const std::string prefix =
            std::string("#version 130\n#define CUT ") + (cut ? "1\n" : "0\n");
        const std::string vertex = prefix + kGeometryVertex;
        const std::string fragment = prefix + kCutTest + kGeometryFragment;
        if (!mGeometry[cut].build(gl, vertex.c_str(), fragment.c_str(), error)) return false;
        const ShaderProgram& g = mGeometry[cut];
        mGeo[cut] = {g.uniform(gl, "modelview"),   g.uniform(gl, "projection"),
                     g.uniform(gl, "normalMatrix"), g.uniform(gl, "objectId"),
                     g.uniform(gl, "orthographic"), g.uniform(gl, "depthRange"),
                     g.uniform(gl, "noMaterial"),  g.uniform(gl, "thinLines"),
                     g.uniform(gl, "cutTexture"),  g.uniform(gl, "cutTextured"),
                     g.uniform(gl, "alphaFunc"),   g.uniform(gl, "alphaRef")};
    }
    if (!mDetect.build(gl, kFullscreenVertex, detect.c_str(), error) ||
        !mDirect[0].build(gl, kPlacedVertex, direct[0].c_str(), error) ||
        !mDirect[1].build(gl, kPlacedVertex, direct[1].c_str(), error) ||
        !mDilate.build(gl, kFullscreenVertex, kDilateFragment, error) ||
        !mComposite[0].build(gl, kFullscreenVertex, composite[0].c_str(), error) ||
        !mComposite[1].build(gl, kFullscreenVertex, composite[1].c_str(), error)) {
        return false;
    }
    auto findOperator = [&](ShaderProgram& program, Operator& op) {
        op = {program.uniform(gl, "attributes"), program.uniform(gl, "rect"),
              program.uniform(gl, "depthStep"), program.uniform(gl, "creaseCosine"),
              program.uniform(gl, "colourThreshold"), program.uniform(gl, "objectSeams")};
    };
    auto findFog = [&](ShaderProgram& program, InkFog& u) {
        u = {program.uniform(gl, "fogMode"), program.uniform(gl, "fogRange"),
             program.uniform(gl, "fogColour"), program.uniform(gl, "fogDepth"),
             program.uniform(gl, "windowRange")};
    };
    findOperator(mDetect, mDet);
    for (int f = 0; f < 2; ++f) {
        ShaderProgram& d = mDirect[f];
        ShaderProgram& c = mComposite[f];
        findOperator(d, mDir[f]);
        findFog(d, mDirFog[f]);
        findFog(c, mComFog[f]);
        mDirU[f] = {d.uniform(gl, "origin"),    d.uniform(gl, "cover"),
                    d.uniform(gl, "colours"),   d.uniform(gl, "depthBias"),
                    d.uniform(gl, "modelview"), d.uniform(gl, "projection")};
        mCom[f] = {c.uniform(gl, "dilated"), c.uniform(gl, "attributes"),
                   c.uniform(gl, "rect"),    c.uniform(gl, "origin"),
                   c.uniform(gl, "radius"),  c.uniform(gl, "widths"),
                   c.uniform(gl, "colours"), c.uniform(gl, "depthBias")};
    }
    mDil = {mDilate.uniform(gl, "edges"), mDilate.uniform(gl, "rect"),
            mDilate.uniform(gl, "radius")};

    mWidths = {float(ctx.param(kStyle, "silhouette_width")),
               float(ctx.param(kStyle, "crease_width")),
               float(ctx.param(kStyle, "material_width"))};
    mInks[0] = inkClass(ctx, kStyle, "silhouette_lightness");
    mInks[1] = inkClass(ctx, kStyle, "crease_lightness");
    mInks[2] = inkClass(ctx, kStyle, "material_lightness");
    mDepthThreshold = float(ctx.param(kStyle, "depth_threshold"));
    mCreaseCosine = float(std::cos(glm::radians(ctx.param(kStyle, "crease_angle"))));
    mColourThreshold = float(ctx.param(kStyle, "colour_threshold"));
    mObjectSeams = ctx.param(kStyle, "object_seams") >= 0.5;
    mDetailSize = float(ctx.param(kStyle, "detail_size"));
    mThinSize = float(ctx.param(kStyle, "thin_size"));
    mPass = Pass(std::clamp(int(std::lround(ctx.param(kStyle, "pass"))), 0, 2));
    // Far enough for the widest class (see the composite's coverage).
    const float widest = std::max({mWidths.x, mWidths.y, mWidths.z});
    mRadius = int(std::ceil(0.5f * widest));
    // The band's outer side lies one pixel off the scene, the line up to the radius beyond.
    mMargin = mRadius + 2;

    const float triangle[] = {-1.0f, -1.0f, 0.0f, 3.0f, -1.0f, 0.0f, -1.0f, 3.0f, 0.0f};
    ObjectNames::reserve(gl, ObjectNames::Kind::Buffer, 1, &mTriangle);
    gl.BindBuffer(GL_ARRAY_BUFFER, mTriangle);
    gl.BufferData(GL_ARRAY_BUFFER, sizeof(triangle), triangle, GL_STATIC_DRAW);
    gl.BindBuffer(GL_ARRAY_BUFFER, 0);
    GLfloat lineWidths[2] = {1.0f, 1.0f}, pointSizes[2] = {1.0f, 1.0f};
    gl.GetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, lineWidths);
    gl.GetFloatv(GL_ALIASED_POINT_SIZE_RANGE, pointSizes);
    mWideLines = lineWidths[1] >= kNearWidth && pointSizes[1] >= kNearWidth;
    return true;
}

bool EdgesStyle::planNear(const Scene& scene, StyleContext& ctx, const glm::ivec4& rect)
{
    // Drawn more than once, a pixel must come out the same: ink of full coverage (widths of 2
    // and more; thinner lines blend a fraction of their colour).
    if (mPass == Pass::Full || !mWideLines) return false;
    for (int c = 0; c < 3; ++c) {
        if (mWidths[c] > 0.0f && mWidths[c] < 2.0f) return false;
    }
    // Every pixel the operator can mark lies near some object's feature lines, and within
    // that object's box on screen (with the lines' margin): each object covers its own either
    // way, the cheaper one. The lines' fragments, hidden parts included: n lines spread over
    // an object s pixels across are together about 2 s sqrt(n) long (a grid's are; one box's
    // 12 edges too), and each line's two end points add a square each. Setting up a wide line
    // and its points costs llvmpipe about as much as kLineSetup fragments (measured on
    // neverball's level: 8,174 lines took longer than the 448,800 pixels they lay in).
    // The boxes are run as their union, in tiles (mBoxes): overlapping boxes (a forest of
    // cut-outs) do not run the operator twice over a pixel.
    const glm::vec2 extent(rect.z - rect.x, rect.w - rect.y);
    const double area = double(extent.x) * double(extent.y);
    const float widest = glm::length(extent);
    mBoxes.reset(rect);
    double lineFragments = 0.0, boxFragments = 0.0;
    bool whole = false;
    mNearBy.assign(scene.objects.size(), NearBy::None);
    for (size_t i = 0; i < scene.objects.size() && lineFragments + boxFragments < area; ++i) {
        const SceneObject& o = scene.objects[i];
        if (!o.mesh) continue;
        // A cut-out's lines follow its cut, not its polygons' edges: its box.
        const bool cut = o.alphaFunc != GL_ALWAYS;
        const double n =
            0.5 * double(ctx.meshes.bindDerived(ctx.gl, *o.mesh, &FeatureLines::collect));
        if ((n <= 0.0 && !cut) || mFootprints[i].fineCut || !mFootprints[i].onScreen) continue;
        Footprint& f = mFootprints[i];
        const double across = std::min(f.size, widest);
        const double lines = kNearWidth * (2.0 * across * std::sqrt(n) + 2.0 * kNearWidth * n) +
                             kLineSetup * n;
        f.box = glm::ivec4(glm::max(glm::ivec2(f.box), glm::ivec2(rect)),
                           glm::min(glm::ivec2(f.box.z, f.box.w), glm::ivec2(rect.z, rect.w)));
        const double box = f.size < INFINITY && f.box.x < f.box.z && f.box.y < f.box.w
                               ? double(f.box.z - f.box.x) * double(f.box.w - f.box.y)
                               : INFINITY;
        const bool byLines = !cut && (mPass == Pass::Lines || lines <= box);
        mNearBy[i] = byLines ? NearBy::Lines : NearBy::Box;
        if (byLines) {
            lineFragments += lines;
        } else if (box == INFINITY) {
            boxFragments = INFINITY;
            whole = cut; // a cut-out of no known box on screen: the whole rectangle
        } else {
            boxFragments += double(mBoxes.add(f.box));
        }
    }
    ctx.gl.DisableVertexAttribArray(4); // MeshBuffers::draw's rule
    return !whole && (mPass == Pass::Lines || lineFragments + boxFragments < area);
}

void EdgesStyle::drawCutOut(StyleContext& ctx, const SceneObject& o, const Geometry& u)
{
    const GlFunctions& gl = ctx.gl;
    gl.Uniform1i(u.alphaFunc, int(o.alphaFunc) - GL_NEVER);
    gl.Uniform1f(u.alphaRef, o.alphaRef);
    gl.Uniform1i(u.cutTexture, 0);
    gl.ActiveTexture(GL_TEXTURE0);
    auto textured = [&](GLuint texture) {
        gl.Uniform1i(u.cutTextured, texture != 0 ? 1 : 0);
        gl.BindTexture(GL_TEXTURE_2D, textureName(texture));
    };
    if (o.textureRuns.empty()) {
        textured(o.texture);
        ctx.meshes.draw(gl, *o.mesh);
    } else {
        for (const SceneObject::TextureRun& run : o.textureRuns) {
            textured(run.texture);
            ctx.meshes.drawFaces(gl, *o.mesh, run.firstFace, run.faceCount);
        }
    }
    gl.BindTexture(GL_TEXTURE_2D, 0);
}

void EdgesStyle::drawFullscreen(const GlFunctions& gl)
{
    gl.BindBuffer(GL_ARRAY_BUFFER, mTriangle);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    gl.EnableVertexAttribArray(0);
    for (GLuint a = 1; a < 4; ++a) gl.DisableVertexAttribArray(a);
    gl.DrawArrays(GL_TRIANGLES, 0, 3);
}

const EdgesStyle::Bounds& EdgesStyle::bounds(const reconstruct::ObjectMesh& mesh)
{
    Bounds& b = mBounds[&mesh];
    b.lastUsed = mFlush;
    if (b.cached && b.contentKey == mesh.contentKey &&
        b.geometryVersion == mesh.geometryVersion) {
        return b;
    }
    b.cached = true;
    b.contentKey = mesh.contentKey;
    b.geometryVersion = mesh.geometryVersion;
    b.empty = true;
    b.unitsPerUv = 0.0f;
    b.lo = glm::vec3(INFINITY);
    b.hi = glm::vec3(-INFINITY);
    // The corners drawn (MeshBuffers draws faces' source vertices).
    for (uint32_t corner : mesh.faceCorners) {
        const glm::vec3& p = mesh.sourceVertices[corner].position;
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) continue;
        b.lo = glm::min(b.lo, p);
        b.hi = glm::max(b.hi, p);
        b.empty = false;
    }
    return b;
}

float EdgesStyle::unitsPerUv(const reconstruct::ObjectMesh& mesh)
{
    Bounds& b = mBounds[&mesh]; // bounds() has brought it up to date this flush
    if (b.unitsPerUv != 0.0f) return b.unitsPerUv;
    double area = 0.0, uvArea = 0.0;
    for (size_t f = 0; f + 2 < mesh.faceCorners.size(); f += 3) {
        const reconstruct::Vertex& v0 = mesh.sourceVertices[mesh.faceCorners[f]];
        const reconstruct::Vertex& v1 = mesh.sourceVertices[mesh.faceCorners[f + 1]];
        const reconstruct::Vertex& v2 = mesh.sourceVertices[mesh.faceCorners[f + 2]];
        const float a = glm::length(glm::cross(v1.position - v0.position,
                                               v2.position - v0.position));
        const glm::vec2 s = v1.texcoord - v0.texcoord, t = v2.texcoord - v0.texcoord;
        const float uv = std::abs(s.x * t.y - s.y * t.x);
        if (!std::isfinite(a) || !std::isfinite(uv)) continue;
        area += a;
        uvArea += uv;
    }
    b.unitsPerUv = area > 0.0 && uvArea > 0.0 ? float(std::sqrt(area / uvArea)) : -1.0f;
    return b.unitsPerUv;
}

bool EdgesStyle::besideView(const glm::vec2& lo, const glm::vec2& hi)
{
    return hi.x < -1.0f || lo.x > 1.0f || hi.y < -1.0f || lo.y > 1.0f;
}

bool EdgesStyle::boxOnScreen(const glm::mat4& m, const Bounds& b, glm::vec2& lo, glm::vec2& hi)
{
    // The box as GL clips it: corners in front of the near plane (z + w >= 0 in clip space)
    // and the points where its edges cross that plane. A wall reaching behind the eye then
    // covers what it covers on screen, not the whole window.
    glm::vec4 clip[8];
    float side[8];
    for (int k = 0; k < 8; ++k) {
        const glm::vec3 p((k & 1) ? b.hi.x : b.lo.x, (k & 2) ? b.hi.y : b.lo.y,
                          (k & 4) ? b.hi.z : b.lo.z);
        clip[k] = m * glm::vec4(p, 1.0f);
        side[k] = clip[k].z + clip[k].w;
    }
    auto add = [&](const glm::vec4& c) {
        // On or in front of the near plane w is positive for any projection GL can draw
        // with; a degenerate one (near plane at the eye) projects nowhere useful.
        if (!(c.w > 1e-6f)) return false;
        const glm::vec2 ndc = glm::vec2(c) / c.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
        return true;
    };
    for (int k = 0; k < 8; ++k) {
        if (side[k] >= 0.0f && !add(clip[k])) return false;
        for (int axis = 1; axis < 8; axis <<= 1) {
            const int j = k | axis;
            if (j == k || (side[k] >= 0.0f) == (side[j] >= 0.0f)) continue;
            const float t = side[k] / (side[k] - side[j]);
            if (!add(clip[k] + (clip[j] - clip[k]) * t)) return false;
        }
    }
    return true;
}

EdgesStyle::Footprint EdgesStyle::footprint(const SceneObject& o, int width, int height)
{
    Footprint f;
    if (!o.mesh) return f;
    const Bounds& b = bounds(*o.mesh);
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    if (b.empty || !boxOnScreen(o.projection * o.modelview, b, lo, hi)) return f;
    // Wholly behind the eye (no point added) or beside the view: nothing of it is drawn.
    if (!(lo.x <= hi.x) || !(lo.y <= hi.y) || besideView(lo, hi)) {
        f.onScreen = false;
        return f;
    }
    const glm::vec2 pixels{float(width), float(height)};
    if (o.alphaFunc != GL_ALWAYS && o.cutFeature > 0.0f) {
        // The cut's parts and holes on screen, by the box's pixels per object-space unit:
        // under kFineCut pixels its lines (one pixel each side of every border of the cut)
        // would leave little of either, a grille or a bare tree's twigs a mesh of ink.
        const glm::vec2 across = (hi - lo) * 0.5f * pixels;
        const glm::vec3 extent = b.hi - b.lo;
        const float span = std::max({extent.x, extent.y, extent.z});
        const float perUv = unitsPerUv(*o.mesh);
        if (span > 0.0f && perUv > 0.0f) {
            const float feature = o.cutFeature * perUv * std::max(across.x, across.y) / span;
            f.fineCut = feature < kFineCut;
        }
    }
    lo = (glm::clamp(lo, -2.0f, 2.0f) * 0.5f + 0.5f) * pixels;
    hi = (glm::clamp(hi, -2.0f, 2.0f) * 0.5f + 0.5f) * pixels;
    f.size = std::max(hi.x - lo.x, hi.y - lo.y);
    f.box = {int(std::floor(lo.x)) - mMargin, int(std::floor(lo.y)) - mMargin,
             int(std::ceil(hi.x)) + mMargin, int(std::ceil(hi.y)) + mMargin};
    return f;
}

bool EdgesStyle::coveredRect(const Scene& scene, int width, int height, glm::ivec4& rect)
{
    ++mFlush;
    glm::vec2 lo(INFINITY), hi(-INFINITY);
    bool whole = false;
    for (const SceneObject& o : scene.objects) {
        if (!o.mesh) continue;
        const Bounds& b = bounds(*o.mesh);
        if (b.empty) continue;
        glm::vec2 objectLo(INFINITY), objectHi(-INFINITY);
        if (!boxOnScreen(o.projection * o.modelview, b, objectLo, objectHi)) {
            whole = true;
            break;
        }
        // Wholly beside the view (trees along a course, off to the side): it draws nothing,
        // and its box would stretch the rectangle over what is there (a sky above the ground).
        if (besideView(objectLo, objectHi)) continue;
        lo = glm::min(lo, objectLo);
        hi = glm::max(hi, objectHi);
    }
    // Forget meshes no longer drawn.
    if (mBounds.size() > 2 * scene.objects.size() + 64) {
        std::erase_if(mBounds, [&](const auto& e) { return e.second.lastUsed != mFlush; });
    }
    if (whole) {
        rect = {0, 0, width, height};
        return true;
    }
    if (!(lo.x <= hi.x) || !(lo.y <= hi.y)) return false;
    const glm::vec2 size{float(width), float(height)};
    // Clamp in NDC first: far-off corners would overflow an int.
    lo = (glm::clamp(lo, -2.0f, 2.0f) * 0.5f + 0.5f) * size;
    hi = (glm::clamp(hi, -2.0f, 2.0f) * 0.5f + 0.5f) * size;
    rect = {std::max(int(std::floor(lo.x)) - mMargin, 0),
            std::max(int(std::floor(lo.y)) - mMargin, 0),
            std::min(int(std::ceil(hi.x)) + mMargin, width),
            std::min(int(std::ceil(hi.y)) + mMargin, height)};
    return rect.x < rect.z && rect.y < rect.w;
}

void EdgesStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    const int width = scene.viewport.z, height = scene.viewport.w;
    if (scene.objects.empty() || width <= 0 || height <= 0) return;
    glm::ivec4 rect; // [x0, y0, x1, y1) in the targets' pixels
    if (!coveredRect(scene, width, height, rect)) return;
    {
        // Within the program's scissor box (window pixels; the targets' start at the viewport).
        const glm::ivec2 origin(scene.viewport);
        const glm::ivec4 box = scene.confined(
            glm::ivec4(origin + glm::ivec2(rect), rect.z - rect.x, rect.w - rect.y));
        if (box.z <= 0 || box.w <= 0) return;
        const glm::ivec2 lo = glm::ivec2(box) - origin;
        rect = glm::ivec4(lo, lo + glm::ivec2(box.z, box.w));
    }
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
    // Every pass only touches the covered rectangle; the operators read nothing outside it.
    const glm::ivec4 inclusive(rect.x, rect.y, rect.z - 1, rect.w - 1);
    gl.Enable(GL_SCISSOR_TEST);
    gl.Scissor(rect.x, rect.y, rect.z - rect.x, rect.w - rect.y);

    // 1. The scene's attributes off screen. The polygon offset is stronger than the one a
    // shading style draws with, so the stored depth never loses against the program's. By
    // units only: one by slope pulls a face seen edge-on further than the face in front of
    // it, through it (a cross of ink on glxgears' face where a flank poked through).
    gl.BindFramebuffer(GL_FRAMEBUFFER, mTargets.geometryFbo());
    gl.ColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE); // every channel of its own targets
    gl.Viewport(0, 0, width, height);
    gl.ClearDepth(1.0);
    gl.DepthMask(GL_TRUE);
    const GLuint background[4] = {0, 0xffffffu, 0, 0}; // no depth, window depth 1, id 0
    gl.ClearBufferuiv(GL_COLOR, 0, background);
    gl.Clear(GL_DEPTH_BUFFER_BIT);
    gl.DepthFunc(GL_LESS);
    gl.PolygonOffset(0.0f, -4.0f);
    mFootprints.clear();
    for (const SceneObject& o : scene.objects) {
        mFootprints.push_back(footprint(o, width, height));
    }
    int current = -1;
    for (const SceneObject& o : scene.objects) {
        const Footprint& f = mFootprints[size_t(&o - scene.objects.data())];
        const int cut = o.alphaFunc != GL_ALWAYS ? 1 : 0;
        if ((cut && f.fineCut) || !f.onScreen) continue; // no lines (footprint())
        if (cut != current) {
            current = cut;
            gl.UseProgram(mGeometry[cut].id());
        }
        const Geometry& u = mGeo[cut];
        const glm::mat3 normalMatrix = glm::inverseTranspose(glm::mat3(o.modelview));
        gl.UniformMatrix4fv(u.modelview, 1, GL_FALSE, glm::value_ptr(o.modelview));
        gl.UniformMatrix4fv(u.projection, 1, GL_FALSE, glm::value_ptr(o.projection));
        gl.UniformMatrix3fv(u.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
        gl.Uniform1f(u.objectId, float(o.id));
        // A projection without a perspective row is orthographic; its P[2][2] is -2/range.
        const bool ortho = o.orthographic();
        gl.Uniform1i(u.orthographic, ortho ? 1 : 0);
        gl.Uniform1f(u.depthRange, 2.0f / std::max(std::abs(o.projection[2][2]), 1e-12f));
        gl.Uniform1i(u.noMaterial, f.size < mDetailSize ? 1 : 0);
        gl.Uniform1i(u.thinLines, f.size < mThinSize ? 1 : 0);
        // What the program culls is not on screen: no line may come from it.
        if (!FaceCulling::begin(gl, o)) continue;
        if (cut) drawCutOut(ctx, o, u);
        else ctx.meshes.draw(gl, *o.mesh);
        FaceCulling::end(gl, o);
    }
    gl.Disable(GL_POLYGON_OFFSET_FILL);
    gl.Disable(GL_DEPTH_TEST);
    gl.DepthMask(GL_FALSE);

    auto setOperator = [&](const Operator& op) {
        gl.Uniform1i(op.attributes, 0);
        gl.Uniform4i(op.rect, inclusive.x, inclusive.y, inclusive.z, inclusive.w);
        gl.Uniform1f(op.depthStep, std::log2(1.0f + mDepthThreshold) * 16777216.0f);
        gl.Uniform1f(op.creaseCosine, mCreaseCosine);
        gl.Uniform1f(op.colourThreshold, mColourThreshold * 255.0f);
        gl.Uniform1i(op.objectSeams, mObjectSeams ? 1 : 0);
    };
    GLint depthBits = 0;
    const bool direct = mRadius <= 1;
    if (!direct) {
        // 2. Edge operator.
        gl.BindFramebuffer(GL_FRAMEBUFFER, mTargets.edgeFbo());
        gl.UseProgram(mDetect.id());
        gl.ActiveTexture(GL_TEXTURE0);
        gl.BindTexture(GL_TEXTURE_2D, mTargets.attributes());
        setOperator(mDet);
        drawFullscreen(gl);

        // 3. Rows of the distance search.
        gl.BindFramebuffer(GL_FRAMEBUFFER, mTargets.dilateFbo());
        gl.UseProgram(mDilate.id());
        gl.BindTexture(GL_TEXTURE_2D, mTargets.edges());
        gl.Uniform1i(mDil.edges, 0);
        gl.Uniform4i(mDil.rect, inclusive.x, inclusive.y, inclusive.z, inclusive.w);
        gl.Uniform1i(mDil.radius, mRadius);
        drawFullscreen(gl);
    }

    // 4. Columns (or the operator itself), coverage and the composite into the program's
    // framebuffer.
    bindBack();
    ctx.colourMaskOn();
    gl.Viewport(scene.viewport.x, scene.viewport.y, width, height);
    gl.Scissor(scene.viewport.x + rect.x, scene.viewport.y + rect.y, rect.z - rect.x,
               rect.w - rect.y);
    gl.GetIntegerv(GL_DEPTH_BITS, &depthBits);
    gl.Enable(GL_DEPTH_TEST);
    gl.DepthFunc(GL_LEQUAL);
    gl.Enable(GL_BLEND);
    gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    // Two steps of the program's depth format: its rounding must not hide the ink.
    const int bits = std::clamp(int(depthBits), 8, 24);
    const float depthBias = 2.0f / float(1 << bits);
    // The fog most of the flush's objects are drawn in (lines of unfogged ones, a HUD's 3D
    // icons, are near the eye or few).
    const SceneObject* fogged = nullptr;
    size_t foggedCount = 0;
    for (const SceneObject& o : scene.objects) {
        if (o.fog.mode == 0) continue;
        if (!fogged) fogged = &o;
        ++foggedCount;
    }
    if (2 * foggedCount <= scene.objects.size()) fogged = nullptr;
    const int f = fogged ? 1 : 0; // the programs with the ink's fog, or without
    const glm::vec3 colours[3] = {mInks[0].on(ctx.page), mInks[1].on(ctx.page),
                                  mInks[2].on(ctx.page)};
    auto setFog = [&](const InkFog& u) {
        if (!fogged) return;
        const SceneObject::Fog& fog = fogged->fog;
        gl.Uniform1f(u.mode, ShadingCommon::fogModeCode(fog.mode));
        gl.Uniform3f(u.range, fog.start, fog.end, fog.density);
        gl.Uniform3fv(u.colour, 1, glm::value_ptr(fog.colour));
        const glm::mat4& p = fogged->projection;
        gl.Uniform3f(u.depth, p[2][2], p[3][2], fogged->orthographic() ? 1.0f : 0.0f);
        gl.Uniform2f(u.windowRange, scene.depthRange.x, scene.depthRange.y);
    };
    if (direct) {
        gl.UseProgram(mDirect[f].id());
        setFog(mDirFog[f]);
        gl.ActiveTexture(GL_TEXTURE0);
        gl.BindTexture(GL_TEXTURE_2D, mTargets.attributes());
        setOperator(mDir[f]);
        gl.Uniform2i(mDirU[f].origin, scene.viewport.x, scene.viewport.y);
        const glm::vec3 cover = glm::min(0.5f * mWidths, glm::vec3(1.0f));
        gl.Uniform3fv(mDirU[f].cover, 1, glm::value_ptr(cover));
        gl.Uniform3fv(mDirU[f].colours, 3, glm::value_ptr(colours[0]));
        gl.Uniform1f(mDirU[f].depthBias, depthBias);
        // The viewport's triangle (and an object's box) as is; feature lines set their own.
        const glm::mat4 identity(1.0f);
        gl.UniformMatrix4fv(mDirU[f].modelview, 1, GL_FALSE, glm::value_ptr(identity));
        gl.UniformMatrix4fv(mDirU[f].projection, 1, GL_FALSE, glm::value_ptr(identity));
    } else {
        const auto& u = mCom[f];
        gl.UseProgram(mComposite[f].id());
        setFog(mComFog[f]);
        gl.ActiveTexture(GL_TEXTURE0);
        gl.BindTexture(GL_TEXTURE_2D, mTargets.dilated());
        gl.ActiveTexture(GL_TEXTURE1);
        gl.BindTexture(GL_TEXTURE_2D, mTargets.attributes());
        gl.Uniform1i(u.dilated, 0);
        gl.Uniform1i(u.attributes, 1);
        gl.Uniform4i(u.rect, inclusive.x, inclusive.y, inclusive.z, inclusive.w);
        gl.Uniform2i(u.origin, scene.viewport.x, scene.viewport.y);
        gl.Uniform1i(u.radius, mRadius);
        gl.Uniform3fv(u.widths, 1, glm::value_ptr(mWidths));
        gl.Uniform3fv(u.colours, 3, glm::value_ptr(colours[0]));
        gl.Uniform1f(u.depthBias, depthBias);
    }
    const bool nearLines = direct && planNear(scene, ctx, rect);
    ++mPasses[nearLines ? 1 : 0];
    if (nearLines) {
        // The operator on the pixels near each object's feature lines, hidden or not (it
        // reads the attributes, not the line); the lines' own depth plays no part. Objects
        // whose lines would cost more: on their box.
        for (const glm::ivec4& b : mBoxes.rects()) {
            gl.Scissor(scene.viewport.x + b.x, scene.viewport.y + b.y, b.z - b.x, b.w - b.y);
            drawFullscreen(gl);
        }
        gl.Scissor(scene.viewport.x + rect.x, scene.viewport.y + rect.y, rect.z - rect.x,
                   rect.w - rect.y);
        gl.LineWidth(kNearWidth);
        gl.PointSize(kNearWidth);
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            if (mNearBy[i] != NearBy::Lines) continue;
            const SceneObject& o = scene.objects[i];
            const GLsizei n = ctx.meshes.bindDerived(gl, *o.mesh, &FeatureLines::collect);
            if (n <= 0) continue;
            gl.UniformMatrix4fv(mDirU[f].modelview, 1, GL_FALSE, glm::value_ptr(o.modelview));
            gl.UniformMatrix4fv(mDirU[f].projection, 1, GL_FALSE, glm::value_ptr(o.projection));
            gl.DrawElements(GL_LINES, n, GL_UNSIGNED_INT, nullptr);
            gl.DrawElements(GL_POINTS, n, GL_UNSIGNED_INT, nullptr);
            gl.DisableVertexAttribArray(4); // MeshBuffers::draw's rule
        }
        gl.LineWidth(1.0f);
        gl.PointSize(1.0f);
    } else {
        drawFullscreen(gl);
    }

    ctx.endScissor(scene);
    for (GLenum unit : {GL_TEXTURE1, GL_TEXTURE0}) {
        gl.ActiveTexture(unit);
        gl.BindTexture(GL_TEXTURE_2D, 0);
    }
}

EdgesStyle::~EdgesStyle()
{
    if (mPasses[0] + mPasses[1] > 0) {
        NPRGL_DEBUG("edges: %llu passes near the feature lines, %llu over the whole rectangle",
                    static_cast<unsigned long long>(mPasses[1]),
                    static_cast<unsigned long long>(mPasses[0]));
    }
}

void EdgesStyle::shutdown(StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    mTargets.destroy(gl);
    if (mTriangle) gl.DeleteBuffers(1, &mTriangle);
    mTriangle = 0;
    for (ShaderProgram* p : {&mGeometry[0], &mGeometry[1], &mDetect, &mDirect[0], &mDirect[1], &mDilate,
                             &mComposite[0], &mComposite[1]}) {
        p->destroy(gl);
    }
    mBounds.clear();
}

} // namespace nprgl::styles
