#include "styles/strokes/StrokePainter.h"

#include "reconstruct/Silhouette.h"

#include <algorithm>
#include <cmath>

namespace nprgl::styles::strokes {

namespace {

glm::vec3 edgeNormal(const reconstruct::ObjectMesh& mesh, uint32_t edge)
{
    // A stroke's edge comes from its chain; a bad one (the builder once read one past its
    // run) gets no normal rather than a read outside the mesh.
    if (edge >= mesh.edges.size()) return glm::vec3(0.0f);
    const reconstruct::EdgeInfo& info = mesh.edges[edge];
    glm::vec3 n(0.0f);
    const uint32_t faces = mesh.faceCount();
    if (info.f0 < faces) n += mesh.faceNormal(info.f0);
    if (info.f1 < faces) n += mesh.faceNormal(info.f1);
    const float len = glm::length(n);
    return len > 0.0f ? n / len : glm::vec3(0.0f);
}

} // namespace

void StrokePainter::paint(const reconstruct::ObjectMesh& mesh, const Polylines& strokes,
                          const View& view, const Options& options, JitterTable& jitter,
                          std::vector<StrokeVertex>& out)
{
    mGeometry.setViewport(view.viewport);
    const glm::mat4 mvp = view.projection * view.modelview;
    const glm::vec3 eye = reconstruct::eyeInObjectSpace(view.modelview);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(view.modelview)));
    const float mvScale = std::max(glm::length(glm::vec3(view.modelview[0])), 1e-12f);
    // Object units per pixel at clip w = 1 (times w for perspective; w is 1 in orthographic).
    const float focal = std::max(std::abs(view.projection[1][1]), 1e-12f);
    const float unitsPerPixel =
        2.0f / (float(std::max(view.viewport.w, 1)) * focal) / mvScale;
    const uint32_t passes = std::max(options.passes, 1u);
    const bool jittering = options.jitter > 0.0f;
    const glm::vec3* offsets =
        jittering ? jitter.offsets(mesh, passes, options.seed) : nullptr;
    const uint32_t vertexCount = mesh.vertexCount();
    const glm::vec2 origin(view.viewport.x, view.viewport.y);
    const glm::vec2 halfSize(0.5f * float(view.viewport.z), 0.5f * float(view.viewport.w));

    for (uint32_t s = 0; s < strokes.count(); ++s) {
        const uint32_t begin = strokes.start[s], end = strokes.start[s + 1];
        const uint32_t n = end - begin;
        if (n < 2) continue;
        const bool closed = strokes.closed[s] != 0;
        // Widths do not change between passes.
        mWidths.resize(n);
        for (uint32_t i = 0; i < n; ++i) {
            const ChainPoint& p = strokes.points[begin + i];
            float w = options.width;
            switch (options.widthMode) {
            case WidthMode::Fixed: break;
            case WidthMode::Depth:
                w = std::clamp(options.width * options.depthReference / std::max(p.w, 1e-6f),
                               options.minWidth, options.maxWidth);
                break;
            case WidthMode::Stroke:
                w = std::min(options.maxWidth,
                             options.minWidth * std::pow(options.widthScale, float(i)));
                break;
            case WidthMode::Light: {
                // Thin where the light meets the edge normal head-on, thick where it grazes.
                const uint32_t seg = begin + std::min(i, n - 2);
                const glm::vec3 ne = normalMatrix * edgeNormal(mesh, strokes.edge[seg]);
                const float len = glm::length(ne);
                const float c = len > 0.0f ? glm::dot(ne / len, view.lightDir) : 0.0f;
                const float angle = std::acos(std::clamp(c, -1.0f, 1.0f)) / 3.14159265f;
                w = options.minWidth + (options.maxWidth - options.minWidth) * angle;
                break;
            }
            }
            mWidths[i] = w;
        }
        for (uint32_t pass = 0; pass < passes; ++pass) {
            mPoints.resize(n);
            for (uint32_t i = 0; i < n; ++i) {
                const ChainPoint& p = strokes.points[begin + i];
                const float depthShift = options.biasedDepth ? p.biasedDepth - p.window.z : 0.0f;
                if (!jittering) {
                    mPoints[i] = glm::vec3(p.window.x, p.window.y, p.window.z + depthShift);
                    continue;
                }
                // Local frame: tangent, view direction, and their cross product (oriented
                // along the edge normal, so "normal" mode pushes outwards only).
                const uint32_t a = i + 1 < n ? i : i - 1;
                glm::vec3 tangent = strokes.points[begin + a + 1].object -
                                    strokes.points[begin + a].object;
                const float tl = glm::length(tangent);
                tangent = tl > 0.0f ? tangent / tl : glm::vec3(1.0f, 0.0f, 0.0f);
                glm::vec3 toEye = eye - p.object;
                toEye -= tangent * glm::dot(toEye, tangent);
                const float vl = glm::length(toEye);
                toEye = vl > 0.0f ? toEye / vl : glm::vec3(0.0f, 0.0f, 1.0f);
                glm::vec3 side = glm::cross(tangent, toEye);
                if (glm::dot(side, edgeNormal(mesh, strokes.edge[begin + a])) < 0.0f) side = -side;
                const glm::vec3* base = offsets + size_t(pass) * vertexCount;
                glm::vec3 j = glm::mix(base[p.va], base[p.vb], p.t);
                if (options.jitterMode == JitterMode::Normal) j.z = std::abs(j.z);
                const float scale = options.jitter * unitsPerPixel * p.w;
                const glm::vec3 moved =
                    p.object + scale * (j.x * tangent + j.y * toEye + j.z * side);
                const glm::vec4 clip = mvp * glm::vec4(moved, 1.0f);
                if (clip.w <= 1e-5f) {
                    mPoints[i] = glm::vec3(p.window.x, p.window.y, p.window.z + depthShift);
                    continue;
                }
                const glm::vec3 ndc = glm::vec3(clip) / clip.w;
                mPoints[i] = glm::vec3(origin + (glm::vec2(ndc) + 1.0f) * halfSize,
                                       0.5f * ndc.z + 0.5f + depthShift);
            }
            mGeometry.addStroke(mPoints.data(), mWidths.data(), n, closed, options.opacity, out);
        }
    }
}

} // namespace nprgl::styles::strokes
