#pragma once

// ScenePick: which held-back object of a scene covers a window pixel, nearest first.

#include "styles/Scene.h"

#include <GL/gl.h>

#include <cstdint>

namespace nprgl {

struct PickResult {
    bool hit = false;
    uint32_t object = 0;  // SceneObject::id
    uint32_t face = 0;    // in the object's mesh
    GLuint texture = 0;   // the face's texture (its run's, else the object's), 0: none
    uint32_t faces = 0;   // the object's face count
    uint32_t states = 0;  // the draw states it was drawn in (LeftState bits)
};

// Projects every face of every object that draws colour (not depth-only ones) with its own
// modelview, projection and the scene's viewport, and keeps the nearest face under the pixel
// centre (x, y) in GL window coordinates (y up). On the CPU, once per click: nothing per frame.
PickResult pickScene(const styles::Scene& scene, float x, float y);

} // namespace nprgl
