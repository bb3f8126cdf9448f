#pragma once

#include "Animator.h"
#include "AssimpModel.h"
#include "SkeletonPose.h"

#include <memory>
#include <vector>

namespace character {

// Skeletal animation: linear-blend skinning of assimp's bone-weighted meshes on the CPU.
class SkinAnimator : public Animator {
public:
    bool load(const std::string& path, const std::string& clip, std::string& error) override;
    void pose(double seconds, CharacterPose& pose) override;
    std::string describe() const override;

private:
    struct Influence {
        uint32_t matrix; // index into boneMatrices_
        float weight;
    };
    struct Bone {
        const aiNode* node;
        aiMatrix4x4 offset;
    };

    AssimpModel model_;
    std::unique_ptr<SkeletonPose> skeleton_;
    std::vector<Bone> bones_; // every mesh's bones, then one entry per unskinned mesh
    std::vector<aiMatrix4x4> boneMatrices_;
    std::vector<uint32_t> influenceStart_; // per vertex, into influences_; one extra at the end
    std::vector<Influence> influences_;
    std::vector<aiVector3D> bindPositions_;
    std::vector<aiVector3D> bindNormals_;
    std::vector<uint32_t> indices_;
};

} // namespace character
