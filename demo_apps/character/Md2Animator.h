#pragma once

#include "Animator.h"

#include <string>
#include <vector>

namespace character {

// Morphing: Quake II MD2 keyframes, read here because assimp imports only the first frame,
// blended linearly at the format's 10 frames per second.
class Md2Animator : public Animator {
public:
    bool load(const std::string& path, const std::string& clip, std::string& error) override;
    void pose(double seconds, CharacterPose& pose) override;
    std::string describe() const override;
    const SkinImage* skin() const override { return skin_.width ? &skin_ : nullptr; }
    // The skin to use instead of the one the file names (or <model>.bmp beside it).
    void setSkinPath(const std::string& path) { skinPath_ = path; }

private:
    struct Keyframe {
        std::string name;
        std::vector<float> positions; // x, y, z per vertex, already Y-up
    };

    bool loadSkin(const std::string& modelPath, const std::vector<std::string>& named,
                  std::string& error);

    std::vector<Keyframe> frames_;
    std::vector<uint32_t> triangles_; // MD2 vertex indices: what the normals are built on
    // A vertex of the pose per distinct (MD2 vertex, texture coordinate) corner.
    std::vector<uint32_t> cornerVertex_;
    std::vector<float> cornerTexcoord_;
    std::vector<uint32_t> cornerTriangles_;
    std::vector<Vertex> shared_; // scratch: one per MD2 vertex
    SkinImage skin_;
    std::string skinPath_;
    size_t clipFirst_ = 0;
    size_t clipCount_ = 0;
    std::string clipName_;
};

} // namespace character
