#pragma once

#include "styles/Scene.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace nprgl::styles {

// Where each object's vertices were on the screen in the previous frame, for the motion style:
// the per-vertex screen velocity of an object is its window positions now minus those of the
// same object one frame before.
//
// Which object of the previous frame is "the same" (state only, nothing about a program):
// 1. the one drawn with the same mesh (the reconstruction cache hands a rigid object the same
//    ObjectMesh every frame; only its modelview changes); two objects drawing one mesh pair up
//    in drawing order;
// 2. else the one at the same place in the frame's drawing order, if its topology (vertex and
//    face counts) is the same: an animated (skinned) mesh is updated by the cache, in place or
//    as a copy, so its pointer may change, but its connectivity never does.
// Either way the topology must match, so vertex i then is vertex i now. The mesh pointer is
// only compared, never followed: the previous frame's mesh may be gone.
class MotionHistory {
public:
    struct Motion {
        const std::vector<glm::vec3>* now = nullptr;    // window x, y (pixels), NDC depth
        const std::vector<glm::vec3>* before = nullptr; // the same, a frame ago; null: unknown
    };

    // Starts a flush of `frame`. A new frame makes the current positions the previous ones;
    // a skipped frame or another viewport (than at the last frame's first flush) forgets
    // them. Returns true for a frame's first flush.
    bool beginFlush(uint64_t frame, const glm::ivec4& viewport);
    // Projects the object's vertices (NaN where behind the eye) and finds it a frame ago.
    Motion track(const SceneObject& object);
    void clear();

private:
    struct Track {
        const reconstruct::ObjectMesh* mesh = nullptr; // identity only
        uint32_t vertices = 0;
        uint32_t faces = 0;
        bool taken = false; // matched by an object of the next frame
        std::vector<glm::vec3> window;
    };

    Track* match(const reconstruct::ObjectMesh& mesh, uint32_t slot);

    // Tracks are reused between frames (their vectors keep their storage): the first
    // mNowCount of mNow are this frame's, the first mBeforeCount of mBefore the last one's.
    std::vector<Track> mNow, mBefore;
    size_t mNowCount = 0, mBeforeCount = 0;
    uint64_t mFrame = 0;
    bool mStarted = false;
    glm::ivec4 mViewport{0};      // this flush's
    glm::ivec4 mFrameViewport{0}; // this frame's first flush's
};

} // namespace nprgl::styles
