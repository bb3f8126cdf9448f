#include "styles/outlines/MotionStyle.h"

#include "reconstruct/Silhouette.h"
#include "styles/ObjectNames.h"
#include "styles/StyleRegistry.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace nprgl::styles {

namespace {

constexpr const char* kStyle = "motion";
// A line starts only where the silhouette's outside faces away from the motion by at least
// this cosine (between the outside and the trail): lines leave the object instead of running
// along or across it.
constexpr float kLeaving = 0.3f;
// Width at a line's tail, as a part of its head's: lines taper as they fade.
constexpr float kTailWidth = 0.35f;

// Window pixels to clip space; a small pull towards the eye keeps a line's head, which lies
// at its silhouette point's depth, from losing the depth test against its own object.
const char* kVertex = R"(#version 130
uniform vec4 viewport;
in vec3 position;
in vec3 color;
out vec3 line;
void main()
{
    line = color;
    vec2 ndc = (position.xy - viewport.xy) / viewport.zw * 2.0 - 1.0;
    gl_Position = vec4(ndc, position.z - 0.002, 1.0);
}
)";

// line: opacity, signed pixels from the line's centre, half width; the edge is smoothed
// over a pixel.
const char* kFragment = R"(#version 130
uniform vec3 inkColor;
in vec3 line;
out vec4 fragColor;
void main()
{
    float coverage = clamp(line.z + 0.5 - abs(line.y), 0.0, 1.0);
    fragColor = vec4(inkColor, line.x * coverage);
}
)";

// A fixed integer mix: per-vertex choices that stay the same from frame to frame.
uint32_t mixBits(uint32_t x)
{
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

bool finite(const glm::vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

std::unique_ptr<Style> create() { return std::make_unique<MotionStyle>(); }

} // namespace

StyleInfo motionStyleInfo()
{
    StyleInfo info;
    info.name = kStyle;
    info.summary = "speed lines: strokes from the silhouettes of moving objects, trailing "
                   "opposite their motion between frames, longer the faster, fading over a "
                   "few frames";
    info.role = StyleRole::Outline;
    info.create = &create;
    auto& p = info.params;
    p.push_back(ParamInfo::colour("color", "line colour, hex rrggbb", "000000"));
    p.push_back(ParamInfo::number("min_speed", "screen speed in pixels per frame below which "
                                               "a point draws no line",
                                  0.5, 0.0, 50.0));
    p.push_back(ParamInfo::number("length_scale", "line length per pixel of motion a frame",
                                  8.0, 0.0, 40.0));
    p.push_back(ParamInfo::number("max_length", "longest line in pixels", 80.0, 1.0, 400.0));
    p.push_back(ParamInfo::number("spacing", "least distance in pixels between lines side by "
                                             "side (fewer lines when larger)",
                                  8.0, 1.0, 100.0));
    p.push_back(ParamInfo::number("fade_frames", "frames a line is drawn, fading, counting the one "
                                                 "that made it (1: only that frame)",
                                  4, 1, 30));
    p.push_back(ParamInfo::number("width", "line width in pixels at its head", 1.5, 0.5, 8.0));
    p.push_back(ParamInfo::number("gap", "pixels between the silhouette and a line's head", 3.0,
                                  0.0, 20.0));
    p.push_back(ParamInfo::number("opacity", "opacity of a new line at its head", 0.9, 0.0,
                                  1.0));
    return info;
}

bool MotionStyle::init(StyleContext& ctx, std::string& error)
{
    const GlFunctions& gl = ctx.gl;
    if (!mProgram.build(gl, kVertex, kFragment, error)) return false;
    mViewport = mProgram.uniform(gl, "viewport");
    mColour = mProgram.uniform(gl, "inkColor");
    if (!ParamInfo::parseColour(ctx.text(kStyle, "color"), mColourValue))
        mColourValue = glm::vec3(0.0f);
    mMinSpeed = float(ctx.param(kStyle, "min_speed"));
    mLengthScale = float(ctx.param(kStyle, "length_scale"));
    mMaxLength = float(ctx.param(kStyle, "max_length"));
    mSpacing = float(ctx.param(kStyle, "spacing"));
    mFadeFrames = std::max(1, int(std::lround(ctx.param(kStyle, "fade_frames"))));
    mWidth = float(ctx.param(kStyle, "width"));
    mGap = float(ctx.param(kStyle, "gap"));
    mOpacity = float(ctx.param(kStyle, "opacity"));
    ObjectNames::reserve(gl, ObjectNames::Kind::Buffer, 1, &mBuffer);
    return true;
}

void MotionStyle::addLines(const SceneObject& object, const std::vector<glm::vec3>& now,
                           const std::vector<glm::vec3>& before, uint64_t frame)
{
    const reconstruct::ObjectMesh& mesh = *object.mesh;
    const uint32_t vertices = mesh.vertexCount(), faces = mesh.faceCount();

    // Which faces the eye sees, tested in object space (the plane test survives the affine
    // modelview): from the eye point, or along the view direction when orthographic.
    const bool ortho = object.orthographic();
    const glm::vec3 eye = reconstruct::eyeInObjectSpace(object.modelview);
    const glm::vec3 towards = glm::vec3(glm::inverse(object.modelview) * glm::vec4(0, 0, 1, 0));
    mFront.resize(faces);
    for (uint32_t f = 0; f < faces; ++f) {
        const glm::vec3 view = ortho ? towards : eye - mesh.position(mesh.faceVertices[3 * f]);
        mFront[f] = glm::dot(mesh.faceNormal(f), view) > 0.0f;
    }

    // Silhouette points whose outside faces away from their motion, so a trailing line leaves
    // the object. Outside, on screen: away from the visible face along a silhouette edge (a
    // border counts when its face is visible). A corner has two edges; either will do (a
    // spinning gear's tooth trails on one flank only).
    mLeaving.assign(vertices, -2.0f);
    for (const reconstruct::EdgeInfo& e : mesh.edges) {
        uint32_t face;
        if (e.f0 != reconstruct::kNoIndex && e.f1 != reconstruct::kNoIndex) {
            if (mFront[e.f0] == mFront[e.f1]) continue;
            face = mFront[e.f0] ? e.f0 : e.f1;
        } else {
            face = e.f0 != reconstruct::kNoIndex ? e.f0 : e.f1;
            if (face == reconstruct::kNoIndex || !mFront[face]) continue;
        }
        uint32_t third = mesh.faceVertices[3 * face];
        for (int k = 1; k < 3 && (third == e.v0 || third == e.v1); ++k)
            third = mesh.faceVertices[3 * face + k];
        const glm::vec3 a = now[e.v0], b = now[e.v1], c = now[third];
        if (!finite(a) || !finite(b) || !finite(c)) continue;
        const glm::vec2 d = glm::vec2(b) - glm::vec2(a);
        const float length = glm::length(d);
        if (length < 1e-4f) continue;
        glm::vec2 out = glm::vec2(-d.y, d.x) / length;
        if (glm::dot(out, glm::vec2(c) - glm::vec2(a)) > 0.0f) out = -out;
        for (uint32_t v : {e.v0, e.v1}) {
            if (!finite(before[v])) continue;
            const glm::vec2 back = glm::vec2(before[v]) - glm::vec2(now[v]);
            const float speed = glm::length(back);
            if (speed > 0.0f) mLeaving[v] = std::max(mLeaving[v], glm::dot(out, back) / speed);
        }
    }

    // Of those, the ones fast enough.
    mCandidates.clear();
    for (uint32_t v = 0; v < vertices; ++v) {
        if (mLeaving[v] < kLeaving) continue;
        const glm::vec2 back = glm::vec2(before[v]) - glm::vec2(now[v]);
        const float speed = glm::length(back);
        if (!(speed >= mMinSpeed) || speed <= 0.0f) continue;
        mCandidates.push_back({mixBits(v), v, back / speed, speed});
    }
    std::sort(mCandidates.begin(), mCandidates.end(), [](const Candidate& a, const Candidate& b) {
        return a.priority != b.priority ? a.priority < b.priority : a.vertex < b.vertex;
    });

    // Sparse: a line only where none runs beside it closer than `spacing` (stable: the same
    // vertices win every frame while the view changes little).
    mPlaced.clear();
    for (const Candidate& c : mCandidates) {
        // Lengths vary a little per vertex, as drawn by hand.
        const float unit = float(mixBits(c.vertex ^ 0x9e3779b9u) >> 8) / 16777216.0f;
        const float vary = 0.6f + 0.4f * unit;
        const float length = std::min(mLengthScale * c.speed, mMaxLength) * vary;
        if (length < 3.0f) continue; // a speck, not a line
        const glm::vec2 head = glm::vec2(now[c.vertex]) + c.trail * mGap;
        bool crowded = false;
        for (const glm::vec3& p : mPlaced) {
            const glm::vec2 d = head - glm::vec2(p);
            const float along = std::abs(glm::dot(d, c.trail));
            const float across = std::abs(d.x * c.trail.y - d.y * c.trail.x);
            if (across < mSpacing && along < std::max(length, p.z)) {
                crowded = true;
                break;
            }
        }
        if (crowded) continue;
        mPlaced.push_back(glm::vec3(head, length));
        mLines.push_back({glm::vec3(head, now[c.vertex].z), head + c.trail * length, frame});
    }
}

void MotionStyle::appendQuad(const Line& line, float opacity)
{
    const glm::vec2 head(line.head);
    const glm::vec2 along = line.tail - head;
    const float length = glm::length(along);
    if (length < 1e-3f) return;
    const glm::vec2 side = glm::vec2(-along.y, along.x) / length;
    const float headHalf = 0.5f * mWidth, tailHalf = kTailWidth * headHalf;
    // A pixel of margin on each side for the smoothed edge.
    const float headExtent = headHalf + 1.0f, tailExtent = tailHalf + 1.0f;
    const float z = line.head.z;
    const QuadVertex a{glm::vec3(head + side * headExtent, z), {opacity, headExtent, headHalf}};
    const QuadVertex b{glm::vec3(head - side * headExtent, z), {opacity, -headExtent, headHalf}};
    const QuadVertex c{glm::vec3(line.tail + side * tailExtent, z), {0.0f, tailExtent, tailHalf}};
    const QuadVertex d{glm::vec3(line.tail - side * tailExtent, z),
                       {0.0f, -tailExtent, tailHalf}};
    mUpload.insert(mUpload.end(), {a, b, c, b, d, c});
}

void MotionStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    const glm::ivec4 viewport = scene.viewport;
    if (viewport.z <= 0 || viewport.w <= 0) return;
    const bool firstFlush = mHistory.beginFlush(scene.frame, viewport);
    if (firstFlush) {
        // Lines older than fade_frames go; so do all after a jump back or in a new viewport
        // (their pixels would be somewhere else).
        if (viewport != mLinesViewport) mLines.clear();
        mLinesViewport = viewport;
        std::erase_if(mLines, [&](const Line& l) {
            return l.frame > scene.frame || scene.frame - l.frame >= uint64_t(mFadeFrames);
        });
    }
    const size_t firstNew = mLines.size();
    for (const SceneObject& o : scene.objects) {
        const MotionHistory::Motion motion = mHistory.track(o);
        if (motion.before) addLines(o, *motion.now, *motion.before, scene.frame);
    }

    // A frame's first flush draws the older lines too; a later flush only its own.
    mUpload.clear();
    for (size_t i = firstFlush ? 0 : firstNew; i < mLines.size(); ++i) {
        const Line& l = mLines[i];
        const float age = float(scene.frame - l.frame);
        appendQuad(l, mOpacity * (1.0f - age / float(mFadeFrames)));
    }
    if (mUpload.empty()) return;

    gl.UseProgram(mProgram.id());
    gl.Uniform4f(mViewport, float(viewport.x), float(viewport.y), float(viewport.z),
                 float(viewport.w));
    gl.Uniform3fv(mColour, 1, glm::value_ptr(mColourValue));
    gl.DepthMask(GL_FALSE);
    gl.Enable(GL_BLEND);
    // Lines trail over the background too: their coverage joins the picture's alpha (as
    // strokes' does), or a program's transparent clear would hide them in a saved frame.
    gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    gl.BindBuffer(GL_ARRAY_BUFFER, mBuffer);
    gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(mUpload.size() * sizeof(QuadVertex)),
                  mUpload.data(), GL_STREAM_DRAW);
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(2);
    gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(QuadVertex), nullptr);
    gl.VertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, sizeof(QuadVertex),
                           reinterpret_cast<const void*>(offsetof(QuadVertex, line)));
    gl.DrawArrays(GL_TRIANGLES, 0, GLsizei(mUpload.size()));
    gl.DisableVertexAttribArray(2);
}

void MotionStyle::shutdown(StyleContext& ctx)
{
    mProgram.destroy(ctx.gl);
    if (mBuffer) ctx.gl.DeleteBuffers(1, &mBuffer);
    mBuffer = 0;
    mHistory.clear();
    mLines.clear();
}

} // namespace nprgl::styles
