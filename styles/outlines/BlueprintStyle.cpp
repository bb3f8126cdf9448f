#include "styles/outlines/BlueprintStyle.h"

#include "styles/ObjectNames.h"
#include "styles/StyleRegistry.h"
#include "styles/outlines/EdgeView.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>

namespace nprgl::styles {

namespace {

constexpr const char* kStyle = "blueprint";

// Points arrive in normalised device coordinates; the small pull keeps a line on a visible
// face in front of that face's depth. The texcoord is the pixels from the line's first end.
const char* kVertex = R"(#version 130
in vec3 position;
in float color;
in float texcoord;
out float alpha;
out float dashAt;
void main()
{
    alpha = color;
    dashAt = texcoord;
    gl_Position = vec4(position.xy, position.z - 0.0005, 1.0);
}
)";

// dash > 0: `dash` pixels drawn, `dash` pixels left out, from each line's first end.
const char* kFragment = R"(#version 130
uniform vec3 inkColor;
uniform float dash;
in float alpha;
in float dashAt;
out vec4 fragColor;
void main()
{
    if (dash > 0.0 && mod(dashAt, 2.0 * dash) > dash) discard;
    fragColor = vec4(inkColor, alpha);
}
)";

std::unique_ptr<Style> create() { return std::make_unique<BlueprintStyle>(); }

// Seven-segment glyphs: bit s lights segment s (a top, b upper right, c lower right,
// d bottom, e lower left, f upper left, g middle).
constexpr uint8_t kDigits[10] = {0x3F, 0x06, 0x5B, 0x4F, 0x66, 0x6D, 0x7D, 0x07, 0x7F, 0x6F};
// Segment ends in a 1 x 2 cell, (0, 0) bottom left.
constexpr float kSegments[7][4] = {{0, 2, 1, 2}, {1, 2, 1, 1}, {1, 1, 1, 0}, {0, 0, 1, 0},
                                   {0, 0, 0, 1}, {0, 1, 0, 2}, {0, 1, 1, 1}};

} // namespace

StyleInfo blueprintStyleInfo()
{
    StyleInfo info;
    info.name = kStyle;
    info.summary = "blueprint (HijackGL): white silhouettes, creases and borders run past "
                   "their ends, a faint grid, dimension lines on the longest visible edges";
    info.role = StyleRole::Outline;
    info.create = &create;
    auto& p = info.params;
    p.push_back(ParamInfo::colour("color", "line colour, hex rrggbb", "ffffff"));
    p.push_back(ParamInfo::number("width", "line width in pixels", 1.5, 0.5, 6.0));
    p.push_back(ParamInfo::number("extend", "pixels a line runs past each end", 6.0, 0.0, 30.0));
    p.push_back(ParamInfo::number("grid", "grid spacing in pixels (0: no grid)", 24.0, 0.0,
                                  200.0));
    p.push_back(ParamInfo::number("grid_alpha", "opacity of the grid lines", 0.18, 0.0, 1.0));
    p.push_back(ParamInfo::number("dimensions", "dimension lines on the longest visible "
                                                "straight edges (0: none)",
                                  3, 0, 10));
    p.push_back(ParamInfo::number("hidden", "opacity of the hidden lines, dashed: the parts "
                                            "of the lines behind the scene's surfaces (0: not "
                                            "drawn)",
                                  0.0, 0.0, 1.0));
    p.push_back(ParamInfo::number("dash", "length of a hidden line's dashes and gaps, pixels",
                                  5.0, 1.0, 50.0));
    return info;
}

bool BlueprintStyle::init(StyleContext& ctx, std::string& error)
{
    const GlFunctions& gl = ctx.gl;
    if (!mProgram.build(gl, kVertex, kFragment, error)) return false;
    mInk = mProgram.uniform(gl, "inkColor");
    mDash = mProgram.uniform(gl, "dash");
    mInkColour = ctx.colour(kStyle, "color", "ffffff");
    mWidth = float(ctx.param(kStyle, "width"));
    mExtend = float(ctx.param(kStyle, "extend"));
    mGrid = float(ctx.param(kStyle, "grid"));
    mGridAlpha = float(ctx.param(kStyle, "grid_alpha"));
    mDimensions = int(std::lround(ctx.param(kStyle, "dimensions")));
    mHidden = float(ctx.param(kStyle, "hidden"));
    mDashLength = float(ctx.param(kStyle, "dash"));
    gl.GetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, glm::value_ptr(mLineRange));
    ObjectNames::reserve(gl, ObjectNames::Kind::Buffer, 1, &mBuffer);
    return true;
}

glm::vec2 BlueprintStyle::toPixels(glm::vec3 ndc) const
{
    return {(ndc.x * 0.5f + 0.5f) * float(mViewport[2]) + float(mViewport[0]),
            (ndc.y * 0.5f + 0.5f) * float(mViewport[3]) + float(mViewport[1])};
}

glm::vec3 BlueprintStyle::fromPixels(glm::vec2 p, float z) const
{
    return {(p.x - float(mViewport[0])) / float(mViewport[2]) * 2.0f - 1.0f,
            (p.y - float(mViewport[1])) / float(mViewport[3]) * 2.0f - 1.0f, z};
}

void BlueprintStyle::addLine(glm::vec3 a, glm::vec3 b, float alpha, float extendPixels)
{
    const glm::vec2 pa = toPixels(a), pb = toPixels(b);
    float length = glm::length(pb - pa);
    if (extendPixels > 0.0f && length > 1e-3f) {
        // Short edges (a gear's teeth) run past their ends by a quarter of their length.
        const float extra = std::min(extendPixels, 0.25f * length);
        const glm::vec2 step = (pb - pa) / length * extra;
        a = fromPixels(pa - step, a.z);
        b = fromPixels(pb + step, b.z);
        length += 2.0f * extra;
    }
    mLines.push_back({a, alpha, 0.0f});
    mLines.push_back({b, alpha, length});
}

void BlueprintStyle::addText(const std::string& text, glm::vec2 centre, glm::vec2, float alpha)
{
    // Upright glyphs 5 x 10 pixels with 3 pixels between them, centred on `centre`.
    const float w = 5.0f, h = 5.0f, gap = 3.0f;
    const float width = float(text.size()) * (w + gap) - gap;
    // Inside the viewport, whatever side of the drawing the dimension is on.
    const float left = float(mViewport[0]) + 2.0f, right = left + float(mViewport[2]) - 4.0f;
    const float bottom = float(mViewport[1]) + 2.0f, top = bottom + float(mViewport[3]) - 4.0f;
    float x = std::clamp(centre.x - 0.5f * width, left, std::max(left, right - width));
    const float y = std::clamp(centre.y - h, bottom, std::max(bottom, top - 2.0f * h));
    for (char c : text) {
        if (c == '.') {
            const glm::vec2 p(x + 0.5f * w, y);
            addLine(fromPixels(p, -0.99f), fromPixels(p + glm::vec2(0.0f, 1.5f), -0.99f), alpha,
                    0.0f);
            x += 0.5f * w + gap;
            continue;
        }
        if (c >= '0' && c <= '9') {
            for (int s = 0; s < 7; ++s) {
                if (!(kDigits[c - '0'] & (1 << s))) continue;
                const float* g = kSegments[s];
                addLine(fromPixels({x + g[0] * w, y + g[1] * h}, -0.99f),
                        fromPixels({x + g[2] * w, y + g[3] * h}, -0.99f), alpha, 0.0f);
            }
        }
        x += w + gap;
    }
}

void BlueprintStyle::addDimension(const Dimension& d)
{
    const glm::vec2 pa = toPixels(d.a), pb = toPixels(d.b);
    const glm::vec2 along = glm::normalize(pb - pa);
    glm::vec2 normal(-along.y, along.x);
    // Outward: away from the viewport's centre, so the dimension sits beside the drawing.
    const glm::vec2 centre(float(mViewport[0]) + 0.5f * float(mViewport[2]),
                           float(mViewport[1]) + 0.5f * float(mViewport[3]));
    if (glm::dot(normal, 0.5f * (pa + pb) - centre) < 0.0f) normal = -normal;
    const float offset = 16.0f, arrow = 7.0f;
    const glm::vec2 qa = pa + normal * offset, qb = pb + normal * offset;
    // On top of everything (z near -1): a dimension is an annotation, not part of the drawing.
    auto line = [&](glm::vec2 u, glm::vec2 v) {
        addLine(fromPixels(u, -0.99f), fromPixels(v, -0.99f), 0.9f, 0.0f);
    };
    line(pa + normal * 3.0f, qa + normal * 4.0f); // extension lines
    line(pb + normal * 3.0f, qb + normal * 4.0f);
    line(qa, qb);
    const float c = std::cos(0.45f), s = std::sin(0.45f);
    auto rotate = [&](glm::vec2 v, float sign) {
        return glm::vec2(c * v.x - sign * s * v.y, sign * s * v.x + c * v.y);
    };
    for (float sign : {1.0f, -1.0f}) {
        line(qa, qa + rotate(along, sign) * arrow);
        line(qb, qb - rotate(along, sign) * arrow);
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.2f", double(d.length));
    addText(text, 0.5f * (qa + qb) + normal * 12.0f, along, 0.9f);
}

void BlueprintStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    mViewport = scene.viewport;
    if (mViewport[2] <= 0 || mViewport[3] <= 0) return;
    mLines.clear();
    mGridLines.clear();
    mCandidates.clear();
    // The grid, at the far plane: only the page shows it.
    if (mGrid >= 4.0f) {
        const float x0 = float(mViewport[0]), y0 = float(mViewport[1]);
        const float x1 = x0 + float(mViewport[2]), y1 = y0 + float(mViewport[3]);
        for (float x = x0 + mGrid; x < x1; x += mGrid) {
            mGridLines.push_back({fromPixels({x, y0}, 0.9999f), mGridAlpha, 0.0f});
            mGridLines.push_back({fromPixels({x, y1}, 0.9999f), mGridAlpha, 0.0f});
        }
        for (float y = y0 + mGrid; y < y1; y += mGrid) {
            mGridLines.push_back({fromPixels({x0, y}, 0.9999f), mGridAlpha, 0.0f});
            mGridLines.push_back({fromPixels({x1, y}, 0.9999f), mGridAlpha, 0.0f});
        }
    }
    std::vector<glm::vec3> ndc;
    std::vector<glm::vec3> eye;
    std::vector<bool> inFront;
    for (const SceneObject& o : scene.objects) {
        const reconstruct::ObjectMesh& mesh = *o.mesh;
        const EdgeView view(o);
        ndc.resize(mesh.vertexCount());
        eye.resize(mesh.vertexCount());
        inFront.resize(mesh.vertexCount());
        for (uint32_t v = 0; v < mesh.vertexCount(); ++v) {
            const glm::vec4 e = o.modelview * glm::vec4(mesh.position(v), 1.0f);
            const glm::vec4 c = o.projection * e;
            eye[v] = glm::vec3(e);
            inFront[v] = c.w > 1e-6f;
            ndc[v] = inFront[v] ? glm::vec3(c) / c.w : glm::vec3(0.0f);
        }
        for (size_t e = 0; e < mesh.edges.size(); ++e) {
            const reconstruct::EdgeInfo& edge = mesh.edges[e];
            if (edge.v0 >= ndc.size() || edge.v1 >= ndc.size()) continue;
            if (!inFront[edge.v0] || !inFront[edge.v1]) continue;
            const bool feature = view.feature(e);
            const glm::vec3 mid = 0.5f * (eye[edge.v0] + eye[edge.v1]);
            if (!feature && !view.silhouette(edge, mid)) continue;
            addLine(ndc[edge.v0], ndc[edge.v1], 1.0f, mExtend);
            // A straight edge of the model, on a face that is turned to the eye.
            const bool turnedToEye =
                (edge.f0 != reconstruct::kNoIndex && view.facesEye(edge.f0, mid)) ||
                (edge.f1 != reconstruct::kNoIndex && view.facesEye(edge.f1, mid));
            if (feature && turnedToEye) {
                Dimension d;
                d.a = ndc[edge.v0];
                d.b = ndc[edge.v1];
                d.length = glm::length(mesh.position(edge.v1) - mesh.position(edge.v0));
                d.rank = d.length;
                if (glm::length(toPixels(d.b) - toPixels(d.a)) >= 20.0f) mCandidates.push_back(d);
            }
        }
    }
    // The longest edges; equal lengths keep the order of the meshes (stable between frames).
    std::stable_sort(mCandidates.begin(), mCandidates.end(),
                     [](const Dimension& x, const Dimension& y) { return x.rank > y.rank; });
    // Spread over the drawing: one dimension per neighbourhood.
    const size_t firstDimension = mLines.size();
    std::vector<glm::vec2> placed;
    for (const Dimension& d : mCandidates) {
        if (int(placed.size()) >= mDimensions) break;
        const glm::vec2 mid = 0.5f * (toPixels(d.a) + toPixels(d.b));
        bool crowded = false;
        for (const glm::vec2& p : placed) crowded = crowded || glm::length(p - mid) < 60.0f;
        if (crowded) continue;
        placed.push_back(mid);
        addDimension(d);
    }

    gl.UseProgram(mProgram.id());
    gl.Uniform3fv(mInk, 1, glm::value_ptr(mInkColour));
    gl.DepthMask(GL_FALSE);
    gl.Enable(GL_BLEND);
    gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    gl.BindBuffer(GL_ARRAY_BUFFER, mBuffer);
    gl.Uniform1f(mDash, 0.0f);
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(2);
    gl.EnableVertexAttribArray(3);
    auto draw = [&](const std::vector<Vertex>& v, size_t first, size_t count, float width) {
        if (count == 0) return;
        gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(count * sizeof(Vertex)), v.data() + first,
                      GL_STREAM_DRAW);
        gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), nullptr);
        gl.VertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                               reinterpret_cast<const void*>(offsetof(Vertex, alpha)));
        gl.VertexAttribPointer(3, 1, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                               reinterpret_cast<const void*>(offsetof(Vertex, along)));
        gl.LineWidth(std::clamp(width, mLineRange.x, mLineRange.y));
        gl.DrawArrays(GL_LINES, 0, GLsizei(count));
    };
    draw(mGridLines, 0, mGridLines.size(), 1.0f);
    draw(mLines, 0, firstDimension, mWidth);
    if (mHidden > 0.0f) {
        // Hidden lines: what lies behind the scene's depth, dashed and thinner, like a
        // quantitative-invisibility test of one level against the depth buffer.
        gl.DepthFunc(GL_GREATER);
        gl.Uniform1f(mDash, mDashLength);
        gl.Uniform3fv(mInk, 1, glm::value_ptr(mInkColour));
        for (size_t i = 0; i < firstDimension; ++i) mLines[i].alpha *= mHidden;
        draw(mLines, 0, firstDimension, std::max(1.0f, 0.6f * mWidth));
        gl.Uniform1f(mDash, 0.0f);
        gl.DepthFunc(GL_LEQUAL);
    }
    gl.Disable(GL_DEPTH_TEST); // annotations on top
    draw(mLines, firstDimension, mLines.size() - firstDimension, 1.0f);
    gl.Enable(GL_DEPTH_TEST);
    gl.DisableVertexAttribArray(2);
    gl.DisableVertexAttribArray(3);
}

void BlueprintStyle::shutdown(StyleContext& ctx)
{
    mProgram.destroy(ctx.gl);
    if (mBuffer) ctx.gl.DeleteBuffers(1, &mBuffer);
    mBuffer = 0;
}

} // namespace nprgl::styles
