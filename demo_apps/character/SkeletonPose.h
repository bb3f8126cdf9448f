#pragma once

#include <assimp/scene.h>

#include <string>
#include <unordered_map>
#include <vector>

namespace character {

// Global transforms of every node of an assimp scene at one time of one animation, found by
// interpolating the animation's position, rotation and scaling keys.
class SkeletonPose {
public:
    // animation may be null: then every node keeps its bind transform.
    SkeletonPose(const aiScene* scene, const aiAnimation* animation);

    // With inPlace, the top-most translated node keeps its horizontal start position, so a
    // walking clip stays in front of the camera.
    void evaluate(double seconds, bool inPlace);
    const aiMatrix4x4& global(const aiNode* node) const { return globals_.at(node); }
    double durationSeconds() const;

private:
    void visit(const aiNode* node, const aiMatrix4x4& parent, double ticks, bool inPlace);
    aiMatrix4x4 local(const aiNode* node, double ticks, bool inPlace) const;

    const aiScene* scene_;
    const aiAnimation* animation_;
    std::unordered_map<std::string, const aiNodeAnim*> channels_;
    const aiNodeAnim* rootMotion_ = nullptr;
    std::unordered_map<const aiNode*, aiMatrix4x4> globals_;
};

} // namespace character
