#pragma once

#include <cstdint>
#include <vector>

namespace character {

struct Vertex {
    float position[3];
    float normal[3];
    float texcoord[2] = {0.0f, 0.0f};
};

// A run of triangles drawn with one model transform: the whole body for morphing and
// skinning, one limb for rigid animation.
struct Part {
    uint32_t firstIndex = 0;
    uint32_t indexCount = 0;
    float matrix[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; // column-major
};

// Everything one frame sends to GL.
struct CharacterPose {
    std::vector<Vertex> vertices;
    std::vector<uint32_t> indices;
    std::vector<Part> parts;
};

} // namespace character
