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

private:
    struct Keyframe {
        std::string name;
        std::vector<float> positions; // x, y, z per vertex, already Y-up
    };

    std::vector<Keyframe> frames_;
    std::vector<uint32_t> triangles_;
    size_t clipFirst_ = 0;
    size_t clipCount_ = 0;
    std::string clipName_;
};

} // namespace character
