#include "RigidAnimator.h"

#include <algorithm>
#include <cmath>
#include <unordered_set>

namespace character {

bool RigidAnimator::load(const std::string& path, const std::string& clip, std::string& error)
{
    if (!model_.load(path, clip, error)) return false;
    const aiAnimation* animation = model_.animation;
    std::unordered_set<std::string> joints;
    for (unsigned c = 0; c < animation->mNumChannels; ++c) {
        joints.insert(animation->mChannels[c]->mNodeName.C_Str());
    }

    // Limbs run from each joint to each of its children (end sites included).
    std::vector<std::pair<const aiNode*, aiVector3D>> limbs;
    std::vector<const aiNode*> stack = {model_.scene->mRootNode};
    while (!stack.empty()) {
        const aiNode* node = stack.back();
        stack.pop_back();
        for (unsigned c = 0; c < node->mNumChildren; ++c) {
            const aiNode* child = node->mChildren[c];
            stack.push_back(child);
            const aiMatrix4x4& m = child->mTransformation;
            aiVector3D tip(m.a4, m.b4, m.c4);
            if (joints.count(node->mName.C_Str()) && tip.Length() > 0.0f) {
                limbs.emplace_back(node, tip);
            }
        }
    }
    if (limbs.empty()) {
        error = path + ": has no skeleton to build a figure from";
        return false;
    }
    float longest = 0.0f;
    for (const auto& limb : limbs) longest = std::max(longest, limb.second.Length());
    for (const auto& [joint, tip] : limbs) {
        float half = std::clamp(0.12f * tip.Length(), 0.06f * longest, 0.15f * longest);
        partNodes_.push_back(joint);
        addBox(tip, half);
    }
    skeleton_ = std::make_unique<SkeletonPose>(model_.scene, animation);
    return true;
}

void RigidAnimator::addBox(const aiVector3D& tip, float halfWidth)
{
    // An orthonormal frame with its first axis along the limb.
    aiVector3D along = tip;
    along.Normalize();
    aiVector3D helper = std::fabs(along.y) < 0.9f ? aiVector3D(0, 1, 0) : aiVector3D(1, 0, 0);
    aiVector3D side = (helper ^ along).Normalize();
    aiVector3D up = along ^ side;
    side *= halfWidth;
    up *= halfWidth;
    aiVector3D inset = along * (0.5f * halfWidth); // a small gap at each joint
    aiVector3D start = inset, end = tip - inset;
    if ((end - start) * along <= 0.0f) start = end = tip * 0.5f;

    Part part;
    part.firstIndex = static_cast<uint32_t>(figure_.indices.size());
    auto face = [&](aiVector3D normal, aiVector3D a, aiVector3D b, aiVector3D c, aiVector3D d) {
        uint32_t base = static_cast<uint32_t>(figure_.vertices.size());
        normal.Normalize();
        for (const aiVector3D& p : {a, b, c, d}) {
            figure_.vertices.push_back({{p.x, p.y, p.z}, {normal.x, normal.y, normal.z}});
        }
        figure_.indices.insert(figure_.indices.end(),
                               {base, base + 1, base + 2, base, base + 2, base + 3});
    };
    aiVector3D s0 = start - side - up, s1 = start + side - up, s2 = start + side + up,
               s3 = start - side + up;
    aiVector3D e0 = end - side - up, e1 = end + side - up, e2 = end + side + up,
               e3 = end - side + up;
    face(-along, s0, s3, s2, s1);
    face(along, e0, e1, e2, e3);
    face(-up, s0, s1, e1, e0);
    face(up, s3, e3, e2, s2);
    face(-side, s0, e0, e3, s3);
    face(side, s1, s2, e2, e1);
    part.indexCount = static_cast<uint32_t>(figure_.indices.size()) - part.firstIndex;
    figure_.parts.push_back(part);
}

void RigidAnimator::pose(double seconds, CharacterPose& pose)
{
    skeleton_->evaluate(seconds, true);
    // Undo the file's own placement of the whole scene, as assimp's skinning convention does.
    aiMatrix4x4 rootInverse = model_.scene->mRootNode->mTransformation;
    rootInverse.Inverse();
    for (size_t p = 0; p < partNodes_.size(); ++p) {
        aiMatrix4x4 m = rootInverse * skeleton_->global(partNodes_[p]);
        // assimp matrices are row-major; GL wants columns.
        const float rows[4][4] = {{m.a1, m.a2, m.a3, m.a4}, {m.b1, m.b2, m.b3, m.b4},
                                  {m.c1, m.c2, m.c3, m.c4}, {m.d1, m.d2, m.d3, m.d4}};
        for (int r = 0; r < 4; ++r) {
            for (int c = 0; c < 4; ++c) figure_.parts[p].matrix[4 * c + r] = rows[r][c];
        }
    }
    pose = figure_;
}

std::string RigidAnimator::describe() const
{
    return "rigid: clip " + std::string(model_.animation->mName.C_Str()) + " (" +
           std::to_string(skeleton_->durationSeconds()) + " s), " +
           std::to_string(partNodes_.size()) + " rigid parts";
}

} // namespace character
