#include "styles/outlines/DepthCueStyle.h"

#include "styles/ObjectNames.h"
#include "styles/StyleRegistry.h"
#include "styles/outlines/EdgeView.h"
#include "styles/outlines/OutlineParams.h"

#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstddef>
#include <cmath>
#include <limits>

namespace nprgl::styles {

namespace {

constexpr const char* kStyle = "depthcue";

// Points arrive in eye space; a small pull towards the eye keeps a line on a visible face from
// losing the depth test against that face.
const char* kVertex = R"(#version 130
uniform mat4 projection;
in vec3 position;
in float color;
out float intensity;
void main()
{
    intensity = color;
    gl_Position = projection * vec4(position, 1.0);
    gl_Position.z -= 0.002 * gl_Position.w;
}
)";

const char* kFragment = R"(#version 130
uniform vec3 inkColor;
in float intensity;
out vec4 fragColor;
void main() { fragColor = vec4(inkColor, intensity); }
)";

std::unique_ptr<Style> create() { return std::make_unique<DepthCueStyle>(); }

} // namespace

StyleInfo depthcueStyleInfo()
{
    StyleInfo info;
    info.name = kStyle;
    info.summary = "depth-cued wireframe (HijackGL): edges whose intensity and width fall off "
                   "from the nearest to the farthest point of the scene";
    info.role = StyleRole::Outline;
    info.create = &create;
    auto& p = info.params;
    p.push_back(ParamInfo::choice("edges", "all: every edge of the meshes; features: "
                                           "silhouettes, creases and borders only",
                                  {"all", "features"}, 0));
    p.push_back(ParamInfo::number("near_width", "line width in pixels at the nearest depth",
                                  2.5, 0.5, 10.0));
    p.push_back(ParamInfo::number("far_width", "line width in pixels at the farthest depth",
                                  0.75, 0.5, 10.0));
    p.push_back(ParamInfo::number("near_intensity", "ink opacity at the nearest depth", 1.0,
                                  0.0, 1.0));
    p.push_back(ParamInfo::number("far_intensity", "ink opacity at the farthest depth", 0.15,
                                  0.0, 1.0));
    p.push_back(ParamInfo::number("levels", "width steps between near and far (each a draw)",
                                  4, 1, 8)); // kMaxLevels
    addInkParams(p);
    return info;
}

bool DepthCueStyle::init(StyleContext& ctx, std::string& error)
{
    const GlFunctions& gl = ctx.gl;
    if (!mProgram.build(gl, kVertex, kFragment, error)) return false;
    mProjection = mProgram.uniform(gl, "projection");
    mInk = mProgram.uniform(gl, "inkColor");
    mAllEdges = ctx.param(kStyle, "edges") < 0.5;
    mNearWidth = float(ctx.param(kStyle, "near_width"));
    mFarWidth = float(ctx.param(kStyle, "far_width"));
    mNearIntensity = float(ctx.param(kStyle, "near_intensity"));
    mFarIntensity = float(ctx.param(kStyle, "far_intensity"));
    mLevels = std::clamp(int(std::lround(ctx.param(kStyle, "levels"))), 1, kMaxLevels);
    mInkColour = inkColour(ctx, kStyle);
    gl.GetFloatv(GL_ALIASED_LINE_WIDTH_RANGE, glm::value_ptr(mLineRange));
    ObjectNames::reserve(gl, ObjectNames::Kind::Buffer, 1, &mBuffer);
    return true;
}

void DepthCueStyle::render(const Scene& scene, StyleContext& ctx)
{
    const GlFunctions& gl = ctx.gl;
    // The scene's depth range, from every point of every object.
    float nearest = std::numeric_limits<float>::max(), farthest = -nearest;
    mEye.resize(scene.objects.size());
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        std::vector<glm::vec3>& eye = mEye[i];
        eye.resize(o.mesh->vertexCount());
        for (uint32_t v = 0; v < eye.size(); ++v) {
            const glm::vec4 p = o.modelview * glm::vec4(o.mesh->position(v), 1.0f);
            eye[v] = glm::vec3(p) / (p.w != 0.0f ? p.w : 1.0f);
            nearest = std::min(nearest, -eye[v].z);
            farthest = std::max(farthest, -eye[v].z);
        }
    }
    if (!(farthest >= nearest)) return; // no points at all
    const float span = std::max(farthest - nearest, 1e-6f);
    auto along = [&](const glm::vec3& p) {
        return std::clamp((-p.z - nearest) / span, 0.0f, 1.0f);
    };
    auto intensity = [&](float t) {
        return mNearIntensity + (mFarIntensity - mNearIntensity) * t;
    };

    gl.UseProgram(mProgram.id());
    const glm::vec3 ink = ctx.page.ink(mInkColour);
    gl.Uniform3fv(mInk, 1, glm::value_ptr(ink));
    gl.DepthMask(GL_FALSE);
    gl.Enable(GL_BLEND);
    gl.BlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);
    gl.BindBuffer(GL_ARRAY_BUFFER, mBuffer);
    gl.EnableVertexAttribArray(0);
    gl.EnableVertexAttribArray(2);
    for (size_t i = 0; i < scene.objects.size(); ++i) {
        const SceneObject& o = scene.objects[i];
        const reconstruct::ObjectMesh& mesh = *o.mesh;
        const std::vector<glm::vec3>& eye = mEye[i];
        const EdgeView view(o);
        for (int l = 0; l < mLevels; ++l) mLines[l].clear();
        const size_t edges = mesh.edges.size();
        for (size_t e = 0; e < edges; ++e) {
            const reconstruct::EdgeInfo& edge = mesh.edges[e];
            if (edge.v0 >= eye.size() || edge.v1 >= eye.size()) continue;
            const glm::vec3 a = eye[edge.v0], b = eye[edge.v1];
            if (!mAllEdges && !view.feature(e) && !view.silhouette(edge, 0.5f * (a + b))) {
                continue;
            }
            const float ta = along(a), tb = along(b);
            const int level = std::min(mLevels - 1, int(0.5f * (ta + tb) * float(mLevels)));
            mLines[level].push_back({a, intensity(ta)});
            mLines[level].push_back({b, intensity(tb)});
        }
        mUpload.clear();
        GLint first[kMaxLevels] = {};
        for (int l = 0; l < mLevels; ++l) {
            first[l] = GLint(mUpload.size());
            mUpload.insert(mUpload.end(), mLines[l].begin(), mLines[l].end());
        }
        if (mUpload.empty()) continue;
        gl.BufferData(GL_ARRAY_BUFFER, GLsizeiptr(mUpload.size() * sizeof(LineVertex)),
                      mUpload.data(), GL_STREAM_DRAW);
        gl.VertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(LineVertex), nullptr);
        gl.VertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                               reinterpret_cast<const void*>(offsetof(LineVertex, intensity)));
        gl.UniformMatrix4fv(mProjection, 1, GL_FALSE, glm::value_ptr(o.projection));
        for (int l = 0; l < mLevels; ++l) {
            if (mLines[l].empty()) continue;
            const float t = (float(l) + 0.5f) / float(mLevels);
            const float width = mNearWidth + (mFarWidth - mNearWidth) * t;
            gl.LineWidth(std::clamp(width, mLineRange.x, mLineRange.y));
            gl.DrawArrays(GL_LINES, first[l], GLsizei(mLines[l].size()));
        }
    }
    gl.DisableVertexAttribArray(2);
}

void DepthCueStyle::shutdown(StyleContext& ctx)
{
    mProgram.destroy(ctx.gl);
    if (mBuffer) ctx.gl.DeleteBuffers(1, &mBuffer);
    mBuffer = 0;
}

} // namespace nprgl::styles
