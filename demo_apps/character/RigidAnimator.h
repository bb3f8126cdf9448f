#pragma once

#include "Animator.h"
#include "AssimpModel.h"
#include "SkeletonPose.h"

#include <memory>
#include <vector>

namespace character {

// Rigid keyframe animation: a motion clip (BVH) moves a figure made of one box per bone; each
// box keeps its vertices and gets its own transform every frame.
class RigidAnimator : public Animator {
public:
    bool load(const std::string& path, const std::string& clip, std::string& error) override;
    void pose(double seconds, CharacterPose& pose) override;
    std::string describe() const override;

private:
    void addBox(const aiVector3D& tip, float halfWidth);

    AssimpModel model_;
    std::unique_ptr<SkeletonPose> skeleton_;
    std::vector<const aiNode*> partNodes_; // the joint each part hangs from
    CharacterPose figure_; // boxes in their joints' frames; matrices filled per frame
};

} // namespace character
