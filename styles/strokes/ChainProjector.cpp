#include "styles/strokes/ChainProjector.h"

#include "styles/Scene.h"

#include <algorithm>
#include <cmath>

namespace nprgl::styles::strokes {

namespace {

constexpr float kMinW = 1e-5f;

} // namespace

void ChainProjector::project(const reconstruct::ObjectMesh& mesh, const EdgeChains& chains,
                             const glm::mat4& modelview, const glm::mat4& projection,
                             const glm::ivec4& viewport, float depthTolerance,
                             Polylines& out) const
{
    out.clear();
    const bool perspective = styles::perspective(projection);
    const glm::vec2 origin(viewport.x, viewport.y);
    const glm::vec2 halfSize(0.5f * float(viewport.z), 0.5f * float(viewport.w));
    const reconstruct::Mesh::Point* points = mesh.mesh.points();
    out.points.reserve(chains.vertices.size());
    for (uint32_t c = 0; c < chains.chainCount(); ++c) {
        const uint32_t begin = chains.vertexStart[c], end = chains.vertexStart[c + 1];
        const uint32_t firstEdge = chains.firstEdge(c);
        bool previousBehind = false;
        for (uint32_t i = begin; i < end; ++i) {
            const uint32_t v = chains.vertices[i];
            const auto& q = points[v];
            ChainPoint p;
            p.object = glm::vec3(q[0], q[1], q[2]);
            p.va = p.vb = v;
            const glm::vec4 eye = modelview * glm::vec4(p.object, 1.0f);
            const glm::vec4 clip = projection * eye;
            const bool behind = clip.w <= kMinW;
            p.w = behind ? kMinW : clip.w;
            const glm::vec3 ndc = glm::vec3(clip) / p.w;
            p.window = glm::vec3(origin + (glm::vec2(ndc) + 1.0f) * halfSize,
                                 0.5f * ndc.z + 0.5f);
            // Towards the eye: along the view ray (perspective) or along -z (orthographic).
            glm::vec4 nearer = eye;
            if (perspective) nearer = glm::vec4(glm::vec3(eye) * (1.0f - depthTolerance), 1.0f);
            else nearer.z += depthTolerance * std::max(std::abs(eye.z), 1e-3f);
            const glm::vec4 nearerClip = projection * nearer;
            p.biasedDepth = nearerClip.w > kMinW ? 0.5f * nearerClip.z / nearerClip.w + 0.5f
                                                 : p.window.z;
            const bool last = i + 1 == end;
            // A segment's state is decided when its second point is known; see below.
            out.addPoint(p, last ? 0u : chains.edges[firstEdge + (i - begin)], kUnknown);
            if (i > begin && (behind || previousBehind)) out.state[out.points.size() - 2] = kHidden;
            previousBehind = behind;
        }
        out.endPolyline(chains.closed[c] != 0);
    }
}

} // namespace nprgl::styles::strokes
