#include "styles/outlines/MotionHistory.h"

#include <cmath>
#include <limits>
#include <utility>

namespace nprgl::styles {

bool MotionHistory::beginFlush(uint64_t frame, const glm::ivec4& viewport)
{
    mViewport = viewport; // this flush's objects are projected into it
    if (mStarted && frame == mFrame) return false;
    // Positions in another viewport's pixels say nothing about motion (compared at each
    // frame's first flush).
    const bool next = mStarted && frame == mFrame + 1 && viewport == mFrameViewport;
    std::swap(mNow, mBefore);
    mBeforeCount = next ? mNowCount : 0;
    mNowCount = 0;
    for (size_t i = 0; i < mBeforeCount; ++i) mBefore[i].taken = false;
    mFrame = frame;
    mFrameViewport = viewport;
    mStarted = true;
    return true;
}

MotionHistory::Track* MotionHistory::match(const reconstruct::ObjectMesh& mesh,
                                                 uint32_t slot)
{
    const uint32_t vertices = mesh.vertexCount(), faces = mesh.faceCount();
    auto fits = [&](const Track& t) {
        return !t.taken && t.vertices == vertices && t.faces == faces;
    };
    for (size_t i = 0; i < mBeforeCount; ++i) {
        if (mBefore[i].mesh == &mesh && fits(mBefore[i])) return &mBefore[i];
    }
    // Slots count from 0 in drawing order, so last frame's slot s sits at index s.
    if (slot < mBeforeCount && fits(mBefore[slot])) return &mBefore[slot];
    return nullptr;
}

MotionHistory::Motion MotionHistory::track(const SceneObject& object)
{
    const reconstruct::ObjectMesh& mesh = *object.mesh;
    const uint32_t slot = uint32_t(mNowCount);
    if (mNow.size() <= mNowCount) mNow.emplace_back();
    Track& now = mNow[mNowCount++];
    now.mesh = &mesh;
    now.vertices = mesh.vertexCount();
    now.faces = mesh.faceCount();
    now.taken = false;
    now.window.resize(now.vertices);

    const glm::mat4 mvp = object.projection * object.modelview;
    const glm::vec2 origin(mViewport.x, mViewport.y), size(mViewport.z, mViewport.w);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (uint32_t v = 0; v < now.vertices; ++v) {
        const glm::vec4 clip = mvp * glm::vec4(mesh.position(v), 1.0f);
        if (!(clip.w > 0.0f) || !std::isfinite(clip.x + clip.y + clip.z)) {
            now.window[v] = glm::vec3(nan);
            continue;
        }
        const glm::vec3 ndc = glm::vec3(clip) / clip.w;
        now.window[v] = glm::vec3(origin + (glm::vec2(ndc) * 0.5f + 0.5f) * size, ndc.z);
    }

    Motion motion;
    motion.now = &now.window;
    if (Track* before = match(mesh, slot)) {
        before->taken = true;
        motion.before = &before->window;
    }
    return motion;
}

void MotionHistory::clear()
{
    mNowCount = mBeforeCount = 0;
    mStarted = false;
}

} // namespace nprgl::styles
