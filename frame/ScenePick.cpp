#include "frame/ScenePick.h"

#include "frame/LeaveRules.h"

#include <glm/glm.hpp>

#include <cmath>
#include <limits>

namespace nprgl {

namespace {

// The face's texture: its run's when the object has runs.
GLuint faceTexture(const styles::SceneObject& o, uint32_t face)
{
    for (const styles::SceneObject::TextureRun& run : o.textureRuns) {
        if (face >= run.firstFace && face < run.firstFace + run.faceCount) return run.texture;
    }
    return o.texture;
}

} // namespace

PickResult pickScene(const styles::Scene& scene, float x, float y)
{
    PickResult best;
    float nearest = std::numeric_limits<float>::max();
    const glm::vec4 vp(scene.viewport);
    const glm::vec2 p(x, y);
    for (const styles::SceneObject& o : scene.objects) {
        if (!o.mesh || o.depthOnly) continue;
        const glm::mat4 toClip = o.projection * o.modelview;
        const auto& corners = o.mesh->faceCorners;
        const auto& vertices = o.mesh->sourceVertices;
        const uint32_t faces = uint32_t(corners.size() / 3);
        for (uint32_t f = 0; f < faces; ++f) {
            glm::vec3 w[3];
            bool visible = true;
            for (int k = 0; k < 3 && visible; ++k) {
                const uint32_t c = corners[size_t(f) * 3 + size_t(k)];
                if (c >= vertices.size()) {
                    visible = false;
                    break;
                }
                const glm::vec4 clip = toClip * glm::vec4(vertices[c].position, 1.0f);
                // Behind the eye: such a face is clipped by GL; a pick ignores it.
                visible = clip.w > 0.0f;
                const glm::vec3 ndc = glm::vec3(clip) / clip.w;
                w[k] = glm::vec3(vp.x + (ndc.x + 1.0f) * 0.5f * vp.z,
                                 vp.y + (ndc.y + 1.0f) * 0.5f * vp.w, ndc.z);
            }
            if (!visible) continue;
            // Barycentric coordinates of p in the projected triangle (either winding).
            const glm::vec2 a(w[0]), b(w[1]), c(w[2]);
            const float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
            if (area == 0.0f || !std::isfinite(area)) continue;
            const float u = ((b.x - p.x) * (c.y - p.y) - (c.x - p.x) * (b.y - p.y)) / area;
            const float v = ((c.x - p.x) * (a.y - p.y) - (a.x - p.x) * (c.y - p.y)) / area;
            const float t = 1.0f - u - v;
            if (u < 0.0f || v < 0.0f || t < 0.0f) continue;
            const float depth = u * w[0].z + v * w[1].z + t * w[2].z;
            if (depth < -1.0f || depth > 1.0f || depth >= nearest) continue;
            nearest = depth;
            best.hit = true;
            best.object = o.id;
            best.face = f;
            best.texture = faceTexture(o, f);
            best.faces = faces;
            best.states = LeaveRules::statesOf(o);
        }
    }
    return best;
}

} // namespace nprgl
