#include "SkeletonPose.h"

#include <cmath>

namespace character {

namespace {

double ticksPerSecond(const aiAnimation* animation)
{
    return animation->mTicksPerSecond > 0.0 ? animation->mTicksPerSecond : 25.0;
}

// Index of the last key at or before ticks (0 when ticks precede every key).
template <typename Key>
unsigned keyBefore(const Key* keys, unsigned count, double ticks)
{
    unsigned i = 0;
    while (i + 1 < count && keys[i + 1].mTime <= ticks) ++i;
    return i;
}

template <typename Key>
float blendOf(const Key* keys, unsigned count, unsigned i, double ticks)
{
    if (i + 1 >= count) return 0.0f;
    double span = keys[i + 1].mTime - keys[i].mTime;
    if (span <= 0.0) return 0.0f;
    double t = (ticks - keys[i].mTime) / span;
    return static_cast<float>(t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t));
}

aiVector3D vectorAt(const aiVectorKey* keys, unsigned count, double ticks)
{
    unsigned i = keyBefore(keys, count, ticks);
    float t = blendOf(keys, count, i, ticks);
    if (t == 0.0f) return keys[i].mValue;
    return keys[i].mValue + (keys[i + 1].mValue - keys[i].mValue) * t;
}

aiQuaternion rotationAt(const aiQuatKey* keys, unsigned count, double ticks)
{
    unsigned i = keyBefore(keys, count, ticks);
    float t = blendOf(keys, count, i, ticks);
    if (t == 0.0f) return keys[i].mValue;
    aiQuaternion q;
    aiQuaternion::Interpolate(q, keys[i].mValue, keys[i + 1].mValue, t);
    return q.Normalize();
}

} // namespace

SkeletonPose::SkeletonPose(const aiScene* scene, const aiAnimation* animation)
    : scene_(scene), animation_(animation)
{
    if (!animation_) return;
    for (unsigned c = 0; c < animation_->mNumChannels; ++c) {
        const aiNodeAnim* channel = animation_->mChannels[c];
        channels_[channel->mNodeName.C_Str()] = channel;
    }
    // Breadth-first, so the first translated node found is the top-most one.
    std::vector<const aiNode*> level = {scene_->mRootNode};
    while (!level.empty() && !rootMotion_) {
        std::vector<const aiNode*> next;
        for (const aiNode* node : level) {
            auto found = channels_.find(node->mName.C_Str());
            if (found != channels_.end() && found->second->mNumPositionKeys > 1) {
                rootMotion_ = found->second;
                break;
            }
            next.insert(next.end(), node->mChildren, node->mChildren + node->mNumChildren);
        }
        level.swap(next);
    }
}

double SkeletonPose::durationSeconds() const
{
    return animation_ ? animation_->mDuration / ticksPerSecond(animation_) : 0.0;
}

void SkeletonPose::evaluate(double seconds, bool inPlace)
{
    double ticks = 0.0;
    if (animation_ && animation_->mDuration > 0.0) {
        ticks = std::fmod(seconds * ticksPerSecond(animation_), animation_->mDuration);
    }
    visit(scene_->mRootNode, aiMatrix4x4(), ticks, inPlace);
}

void SkeletonPose::visit(const aiNode* node, const aiMatrix4x4& parent, double ticks,
                         bool inPlace)
{
    aiMatrix4x4 global = parent * local(node, ticks, inPlace);
    globals_[node] = global;
    for (unsigned c = 0; c < node->mNumChildren; ++c) {
        visit(node->mChildren[c], global, ticks, inPlace);
    }
}

aiMatrix4x4 SkeletonPose::local(const aiNode* node, double ticks, bool inPlace) const
{
    auto found = channels_.find(node->mName.C_Str());
    if (found == channels_.end()) return node->mTransformation;
    const aiNodeAnim* channel = found->second;

    aiVector3D bindScale, bindPosition;
    aiQuaternion bindRotation;
    node->mTransformation.Decompose(bindScale, bindRotation, bindPosition);
    aiVector3D position = channel->mNumPositionKeys
        ? vectorAt(channel->mPositionKeys, channel->mNumPositionKeys, ticks) : bindPosition;
    aiQuaternion rotation = channel->mNumRotationKeys
        ? rotationAt(channel->mRotationKeys, channel->mNumRotationKeys, ticks) : bindRotation;
    aiVector3D scale = channel->mNumScalingKeys
        ? vectorAt(channel->mScalingKeys, channel->mNumScalingKeys, ticks) : bindScale;
    if (inPlace && channel == rootMotion_) {
        position.x = channel->mPositionKeys[0].mValue.x;
        position.z = channel->mPositionKeys[0].mValue.z;
    }
    return aiMatrix4x4(scale, rotation, position);
}

} // namespace character
